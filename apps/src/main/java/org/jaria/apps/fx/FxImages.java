package org.jaria.apps.fx;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import javafx.scene.image.Image;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.PixelReader;
import javafx.scene.image.WritableImage;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.RgbImage;

/** Converting between JavaFX images and {@link RgbImage}s, and writing PNG files. */
public final class FxImages {

  private FxImages() {}

  /** The pixels of a JavaFX image, flattened onto white where they are transparent. */
  public static RgbImage toRgb(Image image) {
    int w = (int) image.getWidth();
    int h = (int) image.getHeight();
    int[] argb = new int[w * h];
    PixelReader r = image.getPixelReader();
    r.getPixels(0, 0, w, h, PixelFormat.getIntArgbInstance(), argb, 0, w);
    for (int i = 0; i < argb.length; i++) {
      int p = argb[i];
      int a = p >>> 24;
      if (a == 255) {
        argb[i] = p & 0xFFFFFF;
      } else {
        int red = blend((p >>> 16) & 0xFF, a);
        int green = blend((p >>> 8) & 0xFF, a);
        int blue = blend(p & 0xFF, a);
        argb[i] = (red << 16) | (green << 8) | blue;
      }
    }
    return new RgbImage(w, h, argb);
  }

  private static int blend(int c, int a) {
    return (c * a + 255 * (255 - a)) / 255;
  }

  /** A JavaFX image of packed {@code 0xRRGGBB} pixels. */
  public static WritableImage toFx(int[] rgb, int width, int height) {
    WritableImage img = new WritableImage(width, height);
    int[] argb = new int[width * height];
    for (int i = 0; i < argb.length; i++) {
      argb[i] = 0xFF000000 | rgb[i];
    }
    img.getPixelWriter()
        .setPixels(0, 0, width, height, PixelFormat.getIntArgbInstance(), argb, 0, width);
    return img;
  }

  /**
   * Writes an image as PNG. The file is written next to its destination first and then moved into
   * place, so a failure never leaves half a file.
   */
  public static void writePng(Image image, Path file) throws IOException {
    write(ImageFiles.encode(toRgb(image), "png"), file);
  }

  /**
   * Writes {@code bytes} to {@code file} through a file next to it, moved into place when complete.
   * Both get the permissions every new file of the user gets (their umask: usually readable by
   * all), not a temporary file's owner-only ones: a screenshot is made to be shown.
   */
  static void write(byte[] bytes, Path file) throws IOException {
    Path abs = file.toAbsolutePath();
    Path dir = abs.getParent();
    if (dir != null) {
      Files.createDirectories(dir);
    }
    Path tmp = abs.resolveSibling("." + abs.getFileName() + ".writing");
    try {
      Files.write(tmp, bytes);
      Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
    } finally {
      Files.deleteIfExists(tmp);
    }
  }
}
