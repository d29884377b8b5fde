package org.jaria.acts.blob;

import java.util.Arrays;

/**
 * Every connected region (4-connectivity) of one channel in one frame, unfiltered and in raster
 * order of their first pixel: what a reference labelling such as OpenCV's {@code
 * connectedComponentsWithStats} returns. Filled by {@link BlobTracker#components}; useful for
 * training displays and for checking the tracker. Components are numbered from 0.
 */
public final class ChannelComponents {

  int count;
  int[] area = new int[16];
  long[] sumX = new long[16];
  long[] sumY = new long[16];
  int[] left = new int[16];
  int[] right = new int[16];
  int[] top = new int[16];
  int[] bottom = new int[16];

  /** An empty result. */
  public ChannelComponents() {}

  /** Number of components. */
  public int count() {
    return count;
  }

  /** Pixels in component {@code i}. */
  public int area(int i) {
    return area[check(i)];
  }

  /** Leftmost column of component {@code i}. */
  public int left(int i) {
    return left[check(i)];
  }

  /** Rightmost column. */
  public int right(int i) {
    return right[check(i)];
  }

  /** Top row. */
  public int top(int i) {
    return top[check(i)];
  }

  /** Bottom row. */
  public int bottom(int i) {
    return bottom[check(i)];
  }

  /** Exact centre of gravity column. */
  public double xCentroid(int i) {
    return (double) sumX[check(i)] / area[i];
  }

  /** Exact centre of gravity row. */
  public double yCentroid(int i) {
    return (double) sumY[check(i)] / area[i];
  }

  private int check(int i) {
    if (i < 0 || i >= count) {
      throw new IndexOutOfBoundsException("component " + i + " of " + count);
    }
    return i;
  }

  void ensure(int n) {
    if (area.length < n) {
      int cap = Math.max(n, area.length * 2);
      area = Arrays.copyOf(area, cap);
      sumX = Arrays.copyOf(sumX, cap);
      sumY = Arrays.copyOf(sumY, cap);
      left = Arrays.copyOf(left, cap);
      right = Arrays.copyOf(right, cap);
      top = Arrays.copyOf(top, cap);
      bottom = Arrays.copyOf(bottom, cap);
    }
  }
}
