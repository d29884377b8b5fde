package org.jaria.acts.image;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The tutorial picture, re-created: a desk scene with a red book and a red cup (thesis §5.3.12, "se
 * mostrará una imagen, hay un libro rojo y un vaso rojo") plus distractors — a yellow note, a green
 * mug, a blue pen, an orange ball, a pink eraser and a few tiny red specks that ACTS should ignore
 * as noise — under light that falls off from the top left, with sensor noise.
 *
 * <p>Drawn by integer arithmetic and a fixed pseudo-random sequence, so it is identical on every
 * machine. The shipped copies ({@code org/jaria/acts/images/desk-scene.ppm} and {@code .png},
 * 320×240) are this picture; {@link #main} writes them again.
 *
 * <p>Landmarks (320×240 coordinates) for tests and demos: {@link #BOOK} and {@link #CUP} are
 * rectangles inside the two red objects that contain only their red surfaces.
 */
public final class TestScene {

  /** The scene's native width. */
  public static final int WIDTH = 320;

  /** The scene's native height. */
  public static final int HEIGHT = 240;

  /** Class-path location of the PPM copy. */
  public static final String PPM_RESOURCE = "/org/jaria/acts/images/desk-scene.ppm";

  /** Class-path location of the PNG copy. */
  public static final String PNG_RESOURCE = "/org/jaria/acts/images/desk-scene.png";

  /** A rectangle {@code [x0, x1] × [y0, y1]} (inclusive). */
  public record Box(int x0, int y0, int x1, int y1) {
    /** The box in an image of another size. */
    public Box scaled(int width, int height) {
      return new Box(
          x0 * width / WIDTH, y0 * height / HEIGHT, x1 * width / WIDTH, y1 * height / HEIGHT);
    }

    /** Whether {@code (x, y)} is inside. */
    public boolean contains(int x, int y) {
      return x >= x0 && x <= x1 && y >= y0 && y <= y1;
    }
  }

  /** The book's whole extent (cover, spine and page edge). */
  public static final Box BOOK_EXTENT = new Box(40, 128, 150, 200);

  /** A rectangle of red book cover only. */
  public static final Box BOOK = new Box(60, 134, 140, 150);

  /** The cup's body extent. */
  public static final Box CUP_EXTENT = new Box(196, 106, 266, 186);

  /** A rectangle of red cup body only. */
  public static final Box CUP = new Box(208, 125, 234, 175);

  private TestScene() {}

  /** The scene at its native 320×240. */
  public static RgbImage render() {
    int[] px = new int[WIDTH * HEIGHT];
    int seed = 0x2545F491;
    for (int y = 0; y < HEIGHT; y++) {
      for (int x = 0; x < WIDTH; x++) {
        int c = base(x, y);
        // Light from the top left: 105% there, 80% at the bottom right.
        int light = 1050 - 250 * (x * HEIGHT + y * WIDTH) / (2 * WIDTH * HEIGHT);
        int r = ((c >>> 16) & 0xFF) * light / 1000;
        int g = ((c >>> 8) & 0xFF) * light / 1000;
        int b = (c & 0xFF) * light / 1000;
        seed ^= seed << 13;
        seed ^= seed >>> 17;
        seed ^= seed << 5;
        r += ((seed & 0xF) % 11) - 5;
        g += (((seed >>> 4) & 0xF) % 11) - 5;
        b += (((seed >>> 8) & 0xF) % 11) - 5;
        px[y * WIDTH + x] = RgbImage.pack(clamp(r), clamp(g), clamp(b));
      }
    }
    return new RgbImage(WIDTH, HEIGHT, px);
  }

  /** The scene scaled to {@code width × height} (160×120 is ACTS's working size). */
  public static RgbImage render(int width, int height) {
    return render().scaled(width, height);
  }

  /** The name the command lines accept for the shipped scene ({@code acts -f desk-scene}). */
  public static final String BUNDLED_NAME = "desk-scene";

  /**
   * Whether {@code typed}, given where an image file is expected, means the shipped scene: it names
   * no existing file, and is {@code desk-scene}, {@code desk-scene.ppm} or {@code desk-scene.png}.
   */
  public static boolean isBundledName(java.nio.file.Path typed) {
    String n = typed.toString();
    return !java.nio.file.Files.exists(typed)
        && (n.equals(BUNDLED_NAME)
            || n.equals(BUNDLED_NAME + ".ppm")
            || n.equals(BUNDLED_NAME + ".png"));
  }

  /** The shipped PPM copy, read from the class path. */
  public static RgbImage load() {
    try (InputStream in = TestScene.class.getResourceAsStream(PPM_RESOURCE)) {
      if (in == null) {
        throw new IOException(PPM_RESOURCE + " is missing from the class path");
      }
      return ImageFiles.read(in, PPM_RESOURCE);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private static int clamp(int v) {
    return Math.max(0, Math.min(255, v));
  }

  // The unlit colour of a pixel: the top-most object covering it, painted back to front.
  private static int base(int x, int y) {
    // Tiny red specks (noise ACTS should ignore): 2x2 squares.
    if (speck(x, y, 20, 215) || speck(x, y, 300, 220) || speck(x, y, 170, 120)) {
      return RgbImage.pack(190, 35, 40);
    }
    // Blue pen, a thick diagonal line on the desk.
    if (x >= 160 && x <= 230 && Math.abs((y - 215) - (x - 160) / 4) <= 1) {
      return RgbImage.pack(40, 60, 170);
    }
    // Orange ball.
    if (sq(x - 176) + sq(y - 208) <= 12 * 12) {
      int shade = 100 - (sq(x - 172) + sq(y - 203)) / 6;
      return scale(RgbImage.pack(235, 125, 30), 70 + Math.max(0, shade) * 30 / 100);
    }
    // Pink eraser.
    if (x >= 20 && x <= 34 && y >= 176 && y <= 186) {
      return RgbImage.pack(230, 150, 160);
    }
    // Red cup: a slightly tapered cylinder with a handle and a dark rim opening.
    int cup = cup(x, y);
    if (cup != 0) {
      return cup;
    }
    // Green mug.
    if (x >= 272 && x <= 306 && y >= 128 && y <= 184) {
      return scale(RgbImage.pack(45, 140, 65), cylinder(x, 272, 306));
    }
    // Red book lying on the desk: spine on the left, cream page edge at the bottom, gold title.
    if (BOOK_EXTENT.contains(x, y)) {
      if (y >= 196) {
        return RgbImage.pack(232, 226, 205);
      }
      if (x <= 49) {
        return RgbImage.pack(150, 22, 28);
      }
      if (x >= 90 && x <= 126 && y >= 160 && y <= 168) {
        return RgbImage.pack(205, 170, 60);
      }
      return RgbImage.pack(190, 32, 38);
    }
    // Shadow of the book and cup on the desk.
    boolean shadow =
        (x >= 44 && x <= 156 && y > 200 && y <= 205)
            || (x >= 204 && x <= 270 && y > 186 && y <= 191);
    if (y >= 110) {
      // Desk: wood with grain.
      int grain = (x * 7 + (y * y) / 9 + ((x / 13) % 3) * 11) % 23;
      int wood = scale(RgbImage.pack(150, 100, 58), 90 + grain);
      return shadow ? scale(wood, 70) : wood;
    }
    // Yellow sticky note on the wall.
    if (x >= 258 && x <= 298 && y >= 36 && y <= 74) {
      return RgbImage.pack(238, 218, 72);
    }
    // Wall, with a faint skirting line above the desk.
    if (y >= 104) {
      return RgbImage.pack(170, 160, 140);
    }
    return RgbImage.pack(205, 195, 170);
  }

  private static int cup(int x, int y) {
    if (y < 106 || y > 186) {
      return 0;
    }
    // Body narrows from 50 px at the top to 42 px at the bottom, centred on x = 221.
    int half = 25 - (y - 106) * 4 / 80;
    int dx = x - 221;
    if (Math.abs(dx) <= half) {
      if (y <= 112 && sq(dx) * 36 + sq(y - 109) * 625 <= 625 * 36 * 7 / 10) {
        return RgbImage.pack(95, 18, 22); // the dark opening seen over the rim
      }
      return scale(RgbImage.pack(200, 34, 40), cylinder(x, 221 - half, 221 + half));
    }
    // Handle: a ring on the right side.
    int hx = x - 252;
    int hy = y - 145;
    int d = sq(hx) + sq(hy) * 2;
    if (hx > -6 && d >= 9 * 9 && d <= 14 * 14) {
      return RgbImage.pack(185, 30, 36);
    }
    return 0;
  }

  // Cylinder shading: full brightness in the middle, 75% at the edges (percent).
  private static int cylinder(int x, int left, int right) {
    int mid = (left + right) / 2;
    int half = Math.max(1, (right - left) / 2);
    int t = Math.abs(x - mid) * 100 / half;
    return 100 - t * t / 400;
  }

  private static boolean speck(int x, int y, int sx, int sy) {
    return x >= sx && x <= sx + 1 && y >= sy && y <= sy + 1;
  }

  private static int sq(int v) {
    return v * v;
  }

  private static int scale(int rgb, int percent) {
    return RgbImage.pack(
        clamp(((rgb >>> 16) & 0xFF) * percent / 100),
        clamp(((rgb >>> 8) & 0xFF) * percent / 100),
        clamp((rgb & 0xFF) * percent / 100));
  }

  /**
   * Writes {@code desk-scene.ppm} and {@code desk-scene.png} into a folder (default: this module's
   * resource folder when run from the module directory).
   */
  public static void main(String[] args) throws IOException {
    Path dir = Path.of(args.length > 0 ? args[0] : "src/main/resources/org/jaria/acts/images");
    Files.createDirectories(dir);
    RgbImage img = render();
    ImageFiles.write(img, dir.resolve("desk-scene.ppm"));
    ImageFiles.write(img, dir.resolve("desk-scene.png"));
  }
}
