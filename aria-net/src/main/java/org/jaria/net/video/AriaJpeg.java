package org.jaria.net.video;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Locale;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.VideoFrame;

/**
 * A frame as ArNetworking's video data carry it ({@code sendVideo}, {@code getPictureCam1}): ubyte2
 * width, ubyte2 height, then the JPEG file's bytes to the end of the packet. A packet holds at most
 * 32000 bytes, so the JPEG is encoded again at lower qualities until it fits.
 */
public final class AriaJpeg {

  private AriaJpeg() {}

  /** Most JPEG bytes that fit after the width and height. */
  public static final int MAX_JPEG = ArNetPacket.MAX_DATA_LENGTH - 4;

  /**
   * Writes {@code f} (null: no frame yet, sent as a 0 × 0 image with no bytes) at {@code quality}
   * (0..100) into {@code out}.
   */
  public static void write(VideoFrame f, int quality, ArNetPacket out) {
    if (f == null) {
      out.uByte2ToBuf(0).uByte2ToBuf(0);
      return;
    }
    byte[] jpeg = fitting(f, Math.max(5, Math.min(100, quality)));
    out.uByte2ToBuf(f.getWidth()).uByte2ToBuf(f.getHeight()).dataToBuf(jpeg);
  }

  /** The frame as a JPEG of at most {@link #MAX_JPEG} bytes. */
  static byte[] fitting(VideoFrame f, int quality) {
    if (f.getFormat() == VideoFrame.Format.JPEG && f.getData().length <= MAX_JPEG) {
      return f.getData();
    }
    BufferedImage img = image(f);
    for (int q = quality; q >= 5; q -= 15) {
      byte[] b = encode(img, q / 100f);
      if (b.length <= MAX_JPEG) {
        return b;
      }
    }
    // Still too big: halve the picture until it fits.
    while (true) {
      BufferedImage half =
          new BufferedImage(
              Math.max(1, img.getWidth() / 2),
              Math.max(1, img.getHeight() / 2),
              BufferedImage.TYPE_INT_RGB);
      half.getGraphics().drawImage(img, 0, 0, half.getWidth(), half.getHeight(), null);
      img = half;
      byte[] b = encode(img, 0.5f);
      if (b.length <= MAX_JPEG || img.getWidth() == 1) {
        return b;
      }
    }
  }

  private static BufferedImage image(VideoFrame f) {
    if (f.getFormat() == VideoFrame.Format.RGB) {
      BufferedImage img =
          new BufferedImage(f.getWidth(), f.getHeight(), BufferedImage.TYPE_INT_RGB);
      byte[] d = f.getData();
      for (int y = 0, i = 0; y < f.getHeight(); y++) {
        for (int x = 0; x < f.getWidth(); x++, i += 3) {
          img.setRGB(x, y, (d[i] & 0xff) << 16 | (d[i + 1] & 0xff) << 8 | (d[i + 2] & 0xff));
        }
      }
      return img;
    }
    try {
      BufferedImage img = ImageIO.read(new ByteArrayInputStream(f.getData()));
      if (img == null) {
        throw new IllegalArgumentException(
            "a " + f.getFormat().name().toLowerCase(Locale.ROOT) + " frame that does not decode");
      }
      return img;
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private static byte[] encode(BufferedImage img, float quality) {
    ImageWriter w = ImageIO.getImageWritersByFormatName("jpg").next();
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (MemoryCacheImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
      w.setOutput(out);
      ImageWriteParam p = w.getDefaultWriteParam();
      p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
      p.setCompressionQuality(quality);
      BufferedImage rgb = img;
      if (img.getType() != BufferedImage.TYPE_INT_RGB) {
        rgb = new BufferedImage(img.getWidth(), img.getHeight(), BufferedImage.TYPE_INT_RGB);
        rgb.getGraphics().drawImage(img, 0, 0, null);
      }
      w.write(null, new IIOImage(rgb, null, null), p);
    } catch (IOException e) {
      throw new UncheckedIOException("encoding a JPEG in memory cannot fail", e);
    } finally {
      w.dispose();
    }
    return bytes.toByteArray();
  }
}
