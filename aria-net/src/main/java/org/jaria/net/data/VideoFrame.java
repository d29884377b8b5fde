package org.jaria.net.data;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.Locale;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;

/**
 * One camera image ({@code "getVideo"}): compressed (JPEG, PNG) or raw RGB, 8 bits per channel,
 * rows top to bottom.
 */
public final class VideoFrame implements NetEncodable {

  /** How the bytes encode the image. */
  public enum Format {
    /** A JPEG file. */
    JPEG,
    /** A PNG file. */
    PNG,
    /** width × height × 3 bytes, R G B. */
    RGB
  }

  private final long sequence;
  private final Format format;
  private final int width;
  private final int height;
  private final byte[] data;

  /**
   * A frame; {@code data} is copied.
   *
   * @param sequence the source's frame number (a new frame has a new number)
   * @throws IllegalArgumentException if an RGB frame's size does not match
   */
  public VideoFrame(long sequence, Format format, int width, int height, byte[] data) {
    if (format == Format.RGB && data.length != width * height * 3) {
      throw new IllegalArgumentException(
          "an RGB frame of " + width + "x" + height + " needs " + width * height * 3 + " bytes");
    }
    this.sequence = sequence;
    this.format = format;
    this.width = width;
    this.height = height;
    this.data = data.clone();
  }

  /** The frame number. */
  public long getSequence() {
    return sequence;
  }

  /** The encoding. */
  public Format getFormat() {
    return format;
  }

  /** Width, pixels. */
  public int getWidth() {
    return width;
  }

  /** Height, pixels. */
  public int getHeight() {
    return height;
  }

  /** The bytes (a copy). */
  public byte[] getData() {
    return data.clone();
  }

  /** The bytes, read-only, without copying. */
  public ByteBuffer getDataBuffer() {
    return ByteBuffer.wrap(data).asReadOnlyBuffer();
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(5)
        .intToBuf(sequence)
        .strToBuf(format.name())
        .intToBuf(width)
        .intToBuf(height)
        .blobToBuf(data);
  }

  /** Reads what {@link #write} wrote. */
  public static VideoFrame read(ArNetPacket in) {
    int n = Fields.begin(in, 5, "a video frame");
    long seq = in.bufToLong();
    String f = in.bufToStr();
    Format format;
    try {
      format = Format.valueOf(f == null ? "" : f.toUpperCase(Locale.ROOT));
    } catch (IllegalArgumentException e) {
      throw new ArNetPacketException("unknown video format " + f, e);
    }
    int w = in.bufToInt();
    int h = in.bufToInt();
    byte[] d = in.bufToBlob();
    Fields.end(in, n, 5);
    try {
      return new VideoFrame(seq, format, w, h, d);
    } catch (IllegalArgumentException e) {
      throw new ArNetPacketException(e.getMessage(), e);
    }
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof VideoFrame v
        && v.sequence == sequence
        && v.format == format
        && v.width == width
        && v.height == height
        && Arrays.equals(v.data, data);
  }

  @Override
  public int hashCode() {
    return Long.hashCode(sequence) * 31 + Arrays.hashCode(data);
  }

  @Override
  public String toString() {
    return "VideoFrame[" + sequence + ", " + format + " " + width + "x" + height + "]";
  }
}
