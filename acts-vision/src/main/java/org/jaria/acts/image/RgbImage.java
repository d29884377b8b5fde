package org.jaria.acts.image;

import java.util.Arrays;

/**
 * A colour image as packed {@code 0xRRGGBB} ints, row by row (the layout the tracker reads). The
 * pixel array is owned by the image and may be modified in place through {@link #pixels()}; copy
 * with {@link #copy()} before sharing between threads.
 */
public final class RgbImage {

  /**
   * Largest width or height of an image. (The tracker's working size is smaller: ACTS's wire format
   * sends coordinates as 12-bit numbers, so at most 4095.)
   */
  public static final int MAX_SIZE = 16384;

  /** Most pixels in an image (a 64-megapixel photo). */
  public static final int MAX_PIXELS = 1 << 26;

  private final int width;
  private final int height;
  private final int[] pixels;

  /** A black image. */
  public RgbImage(int width, int height) {
    this(width, height, new int[checkSize(width, height)]);
  }

  /** An image that uses (does not copy) {@code pixels}, which must hold {@code width * height}. */
  public RgbImage(int width, int height, int[] pixels) {
    int n = checkSize(width, height);
    if (pixels.length != n) {
      throw new IllegalArgumentException(
          "a " + width + "x" + height + " image needs " + n + " pixels, got " + pixels.length);
    }
    this.width = width;
    this.height = height;
    this.pixels = pixels;
  }

  /** Returns {@code width * height} after checking the size is allowed. */
  public static int checkSize(int width, int height) {
    if (width < 1
        || height < 1
        || width > MAX_SIZE
        || height > MAX_SIZE
        || (long) width * height > MAX_PIXELS) {
      throw new IllegalArgumentException(
          "image size must be 1.."
              + MAX_SIZE
              + " on each side and at most "
              + MAX_PIXELS
              + " pixels, got "
              + width
              + "x"
              + height);
    }
    return width * height;
  }

  /** Width in pixels. */
  public int width() {
    return width;
  }

  /** Height in pixels. */
  public int height() {
    return height;
  }

  /** The pixel array (live, not a copy). */
  public int[] pixels() {
    return pixels;
  }

  /** The packed {@code 0xRRGGBB} pixel at column {@code x}, row {@code y}. */
  public int get(int x, int y) {
    checkInside(x, y);
    return pixels[y * width + x];
  }

  /** Sets the pixel at column {@code x}, row {@code y} (the top byte is ignored). */
  public void set(int x, int y, int rgb) {
    checkInside(x, y);
    pixels[y * width + x] = rgb & 0xFFFFFF;
  }

  /** Whether {@code (x, y)} is inside the image. */
  public boolean contains(int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height;
  }

  private void checkInside(int x, int y) {
    if (!contains(x, y)) {
      throw new IndexOutOfBoundsException(
          "pixel (" + x + ", " + y + ") outside a " + width + "x" + height + " image");
    }
  }

  /** An independent copy. */
  public RgbImage copy() {
    return new RgbImage(width, height, pixels.clone());
  }

  /** Packs 8-bit components into {@code 0xRRGGBB}. */
  public static int pack(int r, int g, int b) {
    return ((r & 0xFF) << 16) | ((g & 0xFF) << 8) | (b & 0xFF);
  }

  /** The image as interleaved R, G, B bytes. */
  public byte[] toRgbBytes() {
    byte[] out = new byte[pixels.length * 3];
    toRgbBytes(pixels, out);
    return out;
  }

  /** Converts packed pixels to interleaved R, G, B bytes ({@code out.length >= 3 * n}). */
  public static void toRgbBytes(int[] pixels, byte[] out) {
    for (int i = 0, j = 0; i < pixels.length; i++, j += 3) {
      int p = pixels[i];
      out[j] = (byte) (p >>> 16);
      out[j + 1] = (byte) (p >>> 8);
      out[j + 2] = (byte) p;
    }
  }

  /** Converts interleaved R, G, B bytes to packed pixels ({@code rgb.length >= 3 * out.length}). */
  public static void fromRgbBytes(byte[] rgb, int[] out) {
    for (int i = 0, j = 0; i < out.length; i++, j += 3) {
      out[i] = ((rgb[j] & 0xFF) << 16) | ((rgb[j + 1] & 0xFF) << 8) | (rgb[j + 2] & 0xFF);
    }
  }

  /**
   * This image resampled to {@code w × h}: area averaging when shrinking (so a 320×240 image
   * becomes a clean 160×120 one), bilinear interpolation when growing. Returns this image itself
   * when the size already matches.
   */
  public RgbImage scaled(int w, int h) {
    checkSize(w, h);
    if (w == width && h == height) {
      return this;
    }
    int[] out = new int[w * h];
    if (w <= width && h <= height) {
      shrink(w, h, out);
    } else {
      grow(w, h, out);
    }
    return new RgbImage(w, h, out);
  }

  // Box filter: each output pixel averages the source area it covers (with fractional edges).
  private void shrink(int w, int h, int[] out) {
    double sx = (double) width / w;
    double sy = (double) height / h;
    for (int oy = 0; oy < h; oy++) {
      double y0 = oy * sy;
      double y1 = y0 + sy;
      for (int ox = 0; ox < w; ox++) {
        double x0 = ox * sx;
        double x1 = x0 + sx;
        double r = 0;
        double g = 0;
        double b = 0;
        double total = 0;
        for (int y = (int) y0; y < Math.min(height, Math.ceil(y1)); y++) {
          double wy = Math.min(y + 1, y1) - Math.max(y, y0);
          for (int x = (int) x0; x < Math.min(width, Math.ceil(x1)); x++) {
            double wgt = wy * (Math.min(x + 1, x1) - Math.max(x, x0));
            int p = pixels[y * width + x];
            r += wgt * ((p >>> 16) & 0xFF);
            g += wgt * ((p >>> 8) & 0xFF);
            b += wgt * (p & 0xFF);
            total += wgt;
          }
        }
        out[oy * w + ox] =
            pack(
                (int) Math.round(r / total),
                (int) Math.round(g / total),
                (int) Math.round(b / total));
      }
    }
  }

  private void grow(int w, int h, int[] out) {
    for (int oy = 0; oy < h; oy++) {
      double fy = Math.max(0, Math.min(height - 1, (oy + 0.5) * height / h - 0.5));
      int y0 = (int) fy;
      int y1 = Math.min(height - 1, y0 + 1);
      double ty = fy - y0;
      for (int ox = 0; ox < w; ox++) {
        double fx = Math.max(0, Math.min(width - 1, (ox + 0.5) * width / w - 0.5));
        int x0 = (int) fx;
        int x1 = Math.min(width - 1, x0 + 1);
        double tx = fx - x0;
        int p00 = pixels[y0 * width + x0];
        int p01 = pixels[y0 * width + x1];
        int p10 = pixels[y1 * width + x0];
        int p11 = pixels[y1 * width + x1];
        int rgb = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
          double top = lerp((p00 >>> shift) & 0xFF, (p01 >>> shift) & 0xFF, tx);
          double bottom = lerp((p10 >>> shift) & 0xFF, (p11 >>> shift) & 0xFF, tx);
          rgb |= ((int) Math.round(lerp(top, bottom, ty)) & 0xFF) << shift;
        }
        out[oy * w + ox] = rgb;
      }
    }
  }

  private static double lerp(double a, double b, double t) {
    return a + (b - a) * t;
  }

  /** This image rotated by 180° (what an upside-down camera needs; ACTS's "inverted image"). */
  public RgbImage rotated180() {
    int[] out = new int[pixels.length];
    for (int i = 0; i < pixels.length; i++) {
      out[pixels.length - 1 - i] = pixels[i];
    }
    return new RgbImage(width, height, out);
  }

  /** Whether the two images have the same size and pixels. */
  public boolean samePixels(RgbImage other) {
    return other.width == width && other.height == height && Arrays.equals(other.pixels, pixels);
  }
}
