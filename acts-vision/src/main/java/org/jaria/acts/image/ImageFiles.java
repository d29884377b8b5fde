package org.jaria.acts.image;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.jaria.acts.ActsFormatException;

/**
 * Reads and writes image files: PPM (binary P6 and text P3, ACTS's own {@code test.ppm} format, 8-
 * or 16-bit samples) by hand, and PNG, JPEG, BMP and GIF through {@code javax.imageio}. A damaged
 * or unsupported file gives an {@link ActsFormatException} naming the file and what is wrong.
 */
public final class ImageFiles {

  /** Files larger than this are refused before reading. */
  public static final long MAX_FILE_BYTES = 256L << 20;

  private ImageFiles() {}

  /** Reads an image file; the format is recognised from its first bytes, not its name. */
  public static RgbImage read(Path file) throws IOException {
    if (!Files.isRegularFile(file)) {
      throw new IOException(file + ": no such image file");
    }
    long size = Files.size(file);
    if (size > MAX_FILE_BYTES) {
      throw new ActsFormatException(
          file.toString(), -1, "too large for an image (" + size + " bytes)");
    }
    return read(Files.readAllBytes(file), file.toString());
  }

  /** Reads an image from a stream (a class-path resource, say). */
  public static RgbImage read(InputStream in, String name) throws IOException {
    byte[] data = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, MAX_FILE_BYTES + 1));
    if (data.length > MAX_FILE_BYTES) {
      throw new ActsFormatException(name, -1, "too large for an image");
    }
    return read(data, name);
  }

  /** Reads an image from its file bytes. */
  public static RgbImage read(byte[] data, String name) throws IOException {
    if (data.length >= 2 && data[0] == 'P' && (data[1] == '6' || data[1] == '3')) {
      return readPpm(data, name);
    }
    BufferedImage img;
    try {
      img = ImageIO.read(new ByteArrayInputStream(data));
    } catch (IOException | RuntimeException e) {
      throw new ActsFormatException(name, -1, "unreadable image (" + e.getMessage() + ")");
    }
    if (img == null) {
      throw new ActsFormatException(
          name, -1, "not an image this program reads (use PPM P6/P3, PNG, JPEG, BMP or GIF)");
    }
    int w = img.getWidth();
    int h = img.getHeight();
    try {
      RgbImage.checkSize(w, h);
    } catch (IllegalArgumentException e) {
      throw new ActsFormatException(name, -1, e.getMessage());
    }
    int[] px = img.getRGB(0, 0, w, h, null, 0, w);
    for (int i = 0; i < px.length; i++) {
      px[i] &= 0xFFFFFF;
    }
    return new RgbImage(w, h, px);
  }

  /**
   * Writes an image; the format follows the file name's extension ({@code .ppm} binary PPM, {@code
   * .png}, {@code .jpg}/{@code .jpeg}, {@code .bmp}).
   */
  public static void write(RgbImage image, Path file) throws IOException {
    String n = file.getFileName().toString().toLowerCase(Locale.ROOT);
    if (n.endsWith(".ppm") || n.endsWith(".pnm")) {
      Files.write(file, toPpm(image));
      return;
    }
    String format;
    if (n.endsWith(".png")) {
      format = "png";
    } else if (n.endsWith(".jpg") || n.endsWith(".jpeg")) {
      format = "jpeg";
    } else if (n.endsWith(".bmp")) {
      format = "bmp";
    } else {
      throw new IOException(file + ": unknown image type; name it .ppm, .png, .jpg or .bmp");
    }
    Files.write(file, encode(image, format));
  }

  /** The image encoded by {@code javax.imageio} ({@code "png"}, {@code "jpeg"}, {@code "bmp"}). */
  public static byte[] encode(RgbImage image, String format) throws IOException {
    BufferedImage img =
        new BufferedImage(image.width(), image.height(), BufferedImage.TYPE_INT_RGB);
    img.setRGB(0, 0, image.width(), image.height(), image.pixels(), 0, image.width());
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    if (!ImageIO.write(img, format, out)) {
      throw new IOException("no image writer for " + format);
    }
    return out.toByteArray();
  }

  /** The image as a binary (P6) PPM file. */
  public static byte[] toPpm(RgbImage image) {
    byte[] head =
        ("P6\n" + image.width() + " " + image.height() + "\n255\n")
            .getBytes(StandardCharsets.US_ASCII);
    byte[] out = new byte[head.length + 3 * image.pixels().length];
    System.arraycopy(head, 0, out, 0, head.length);
    int[] px = image.pixels();
    for (int i = 0, j = head.length; i < px.length; i++, j += 3) {
      out[j] = (byte) (px[i] >>> 16);
      out[j + 1] = (byte) (px[i] >>> 8);
      out[j + 2] = (byte) px[i];
    }
    return out;
  }

  // ---------------------------------------------------------------- PPM

  private static RgbImage readPpm(byte[] data, String name) throws ActsFormatException {
    PpmCursor c = new PpmCursor(data, name);
    boolean binary = data[1] == '6';
    c.pos = 2;
    int w = c.headerNumber("width");
    int h = c.headerNumber("height");
    int max = c.headerNumber("maximum value");
    if (max < 1 || max > 65535) {
      throw c.error("maximum sample value must be 1..65535, got " + max);
    }
    try {
      RgbImage.checkSize(w, h);
    } catch (IllegalArgumentException e) {
      throw c.error(e.getMessage());
    }
    int[] px = new int[w * h];
    if (binary) {
      if (c.pos >= data.length || !isSpace(data[c.pos])) {
        throw c.error("expected one whitespace byte after the header");
      }
      c.pos++;
      int bytesPer = max < 256 ? 1 : 2;
      long need = (long) w * h * 3 * bytesPer;
      if (data.length - c.pos < need) {
        throw c.error(
            "truncated: "
                + w
                + "x"
                + h
                + " pixels need "
                + need
                + " bytes of samples, the file has "
                + (data.length - c.pos));
      }
      int p = c.pos;
      for (int i = 0; i < px.length; i++) {
        int r;
        int g;
        int b;
        if (bytesPer == 1) {
          r = data[p++] & 0xFF;
          g = data[p++] & 0xFF;
          b = data[p++] & 0xFF;
        } else {
          r = ((data[p] & 0xFF) << 8) | (data[p + 1] & 0xFF);
          g = ((data[p + 2] & 0xFF) << 8) | (data[p + 3] & 0xFF);
          b = ((data[p + 4] & 0xFF) << 8) | (data[p + 5] & 0xFF);
          p += 6;
        }
        px[i] = RgbImage.pack(scale(r, max, c), scale(g, max, c), scale(b, max, c));
      }
    } else {
      for (int i = 0; i < px.length; i++) {
        int r = c.sample(max);
        int g = c.sample(max);
        int b = c.sample(max);
        px[i] = RgbImage.pack(scale(r, max, c), scale(g, max, c), scale(b, max, c));
      }
    }
    return new RgbImage(w, h, px);
  }

  private static int scale(int v, int max, PpmCursor c) throws ActsFormatException {
    if (v > max) {
      throw c.error("sample " + v + " exceeds the maximum value " + max);
    }
    return max == 255 ? v : (int) ((v * 255L + max / 2) / max);
  }

  private static boolean isSpace(byte b) {
    return b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == 0x0B || b == 0x0C;
  }

  /** Reads whitespace-separated numbers of a PPM header (with '#' comments). */
  private static final class PpmCursor {
    final byte[] data;
    final String name;
    int pos;

    PpmCursor(byte[] data, String name) {
      this.data = data;
      this.name = name;
    }

    int headerNumber(String what) throws ActsFormatException {
      skipSpaceAndComments();
      return number(what, 1_000_000);
    }

    int sample(int max) throws ActsFormatException {
      skipSpaceAndComments();
      return number("sample", max);
    }

    private void skipSpaceAndComments() {
      while (pos < data.length) {
        if (isSpace(data[pos])) {
          pos++;
        } else if (data[pos] == '#') {
          while (pos < data.length && data[pos] != '\n') {
            pos++;
          }
        } else {
          return;
        }
      }
    }

    private int number(String what, int limit) throws ActsFormatException {
      int start = pos;
      long v = 0;
      while (pos < data.length && data[pos] >= '0' && data[pos] <= '9') {
        v = v * 10 + (data[pos++] - '0');
        if (v > limit) {
          throw error(what + " is too large");
        }
      }
      if (pos == start) {
        throw error(
            pos >= data.length
                ? "file ends where the " + what + " should be (truncated)"
                : "expected a number for the " + what);
      }
      return (int) v;
    }

    ActsFormatException error(String message) {
      return new ActsFormatException(name, -1, "PPM at byte " + pos + ": " + message);
    }
  }
}
