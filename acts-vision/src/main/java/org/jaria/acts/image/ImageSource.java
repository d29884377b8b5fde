package org.jaria.acts.image;

import java.io.IOException;

/**
 * Where the tracker's frames come from: a still image, a folder of images, a live camera, or (added
 * by the simulator) a rendered camera view. Every frame has the source's fixed {@link #width()} ×
 * {@link #height()}; sources that read larger or smaller pictures scale them.
 *
 * <p>Implementing a new source takes three methods: the size and {@link #nextFrame(int[])}. A
 * source is used by one thread at a time; {@link #close()} may be called from another thread to
 * stop it.
 */
public interface ImageSource extends AutoCloseable {

  /** Frame width in pixels. */
  int width();

  /** Frame height in pixels. */
  int height();

  /**
   * Fills {@code rgb} with the next frame as packed {@code 0xRRGGBB} pixels, row by row, blocking
   * until one is available (a camera's next frame; a still image returns at once).
   *
   * @param rgb at least {@code width() * height()} ints
   * @return false when the source has no more frames (the end of a non-looping sequence)
   * @throws IOException if the frame could not be read (unplugged camera, damaged file)
   */
  boolean nextFrame(int[] rgb) throws IOException;

  /**
   * The next frame as interleaved R, G, B bytes (convenience; allocates a temporary int array).
   *
   * @param rgb at least {@code 3 * width() * height()} bytes
   */
  default boolean nextFrame(byte[] rgb) throws IOException {
    int[] px = new int[width() * height()];
    if (!nextFrame(px)) {
      return false;
    }
    RgbImage.toRgbBytes(px, rgb);
    return true;
  }

  /** A short description for logs and the command line, e.g. {@code image test.ppm 160x120}. */
  default String describe() {
    return getClass().getSimpleName() + " " + width() + "x" + height();
  }

  /** Releases the source (camera, files); idempotent. */
  @Override
  default void close() {}
}
