package org.jaria.acts.color;

import java.util.Arrays;

/**
 * The run-length encoding of one classified frame: for each row, the maximal horizontal runs of
 * pixels that share the same non-zero channel mask (bit {@code c} set = interesting to channel
 * {@code c + 1}). Pixels no channel wants are not stored. Filled by {@link
 * LookupTables#encodeRuns}, read by the blob tracker.
 *
 * <p>The buffers grow when a frame has more runs than any frame before (a noisy image can have one
 * run per pixel) and are then reused: after the first such frame, encoding allocates nothing. Not
 * thread-safe; one instance per processing thread.
 */
public final class MaskRuns {

  private static final int INITIAL_CAPACITY = 1024;

  int width;
  int height;
  int count;
  int seen;
  int[] rowStart = new int[1];
  int[] x0 = new int[INITIAL_CAPACITY];
  int[] x1 = new int[INITIAL_CAPACITY];
  int[] mask = new int[INITIAL_CAPACITY];

  /** An empty buffer. */
  public MaskRuns() {}

  /** Width of the encoded frame. */
  public int width() {
    return width;
  }

  /** Height of the encoded frame. */
  public int height() {
    return height;
  }

  /** Number of runs in the frame. */
  public int count() {
    return count;
  }

  /** The OR of every run's mask: the channels that saw at least one pixel. */
  public int seenMask() {
    return seen;
  }

  /** Index of the first run of row {@code y}; {@code rowStart(height())} is {@link #count()}. */
  public int rowStart(int y) {
    return rowStart[y];
  }

  /** First column of run {@code i}. */
  public int x0(int i) {
    return x0[i];
  }

  /** Last column of run {@code i} (inclusive). */
  public int x1(int i) {
    return x1[i];
  }

  /** Channel mask of run {@code i}. */
  public int mask(int i) {
    return mask[i];
  }

  /** The current capacity in runs (grows, never shrinks). */
  public int capacity() {
    return x0.length;
  }

  void reset(int w, int h) {
    if (w <= 0 || h <= 0) {
      throw new IllegalArgumentException("frame size must be positive, got " + w + "x" + h);
    }
    width = w;
    height = h;
    count = 0;
    seen = 0;
    if (rowStart.length < h + 1) {
      rowStart = new int[h + 1];
    }
  }

  /** Makes room for {@code n} more runs. */
  void ensureFree(int n) {
    int need = count + n;
    if (need > x0.length) {
      int cap = Math.max(need, x0.length * 2);
      x0 = Arrays.copyOf(x0, cap);
      x1 = Arrays.copyOf(x1, cap);
      mask = Arrays.copyOf(mask, cap);
    }
  }
}
