package org.jaria.map;

import java.util.Arrays;

/**
 * The sensor points of a map (its {@code DATA} section), in mm. Immutable and stored as two
 * primitive arrays, so a laser-built map with tens of thousands of points costs two int arrays and
 * no per-point objects. Iterate with {@code for (int i = 0; i < p.size(); i++) use(p.x(i),
 * p.y(i));}.
 */
public final class ArMapPoints {

  /** A map without points. */
  public static final ArMapPoints EMPTY = new ArMapPoints(new int[0], new int[0], 0);

  private final int[] xs;
  private final int[] ys;
  private final int size;

  private ArMapPoints(int[] xs, int[] ys, int size) {
    this.xs = xs;
    this.ys = ys;
    this.size = size;
  }

  /**
   * Points from coordinate arrays of equal length (copied).
   *
   * @throws IllegalArgumentException if the lengths differ
   */
  public static ArMapPoints of(int[] xs, int[] ys) {
    if (xs.length != ys.length) {
      throw new IllegalArgumentException(
          "x and y arrays differ in length: " + xs.length + " vs " + ys.length);
    }
    return new ArMapPoints(xs.clone(), ys.clone(), xs.length);
  }

  /** Takes ownership of the first {@code size} entries of the arrays (no copy). */
  static ArMapPoints wrap(int[] xs, int[] ys, int size) {
    return size == 0 ? EMPTY : new ArMapPoints(xs, ys, size);
  }

  /** Number of points. */
  public int size() {
    return size;
  }

  /** Whether there are no points. */
  public boolean isEmpty() {
    return size == 0;
  }

  /** X of point {@code i}, mm. */
  public int x(int i) {
    return xs[check(i)];
  }

  /** Y of point {@code i}, mm. */
  public int y(int i) {
    return ys[check(i)];
  }

  private int check(int i) {
    if (i < 0 || i >= size) {
      throw new IndexOutOfBoundsException("point " + i + " of " + size);
    }
    return i;
  }

  /** A copy of the x coordinates. */
  public int[] xArray() {
    return Arrays.copyOf(xs, size);
  }

  /** A copy of the y coordinates. */
  public int[] yArray() {
    return Arrays.copyOf(ys, size);
  }

  /** Whether the points are in ARIA's sorted order: by x, then by y. */
  public boolean isSorted() {
    for (int i = 1; i < size; i++) {
      if (xs[i - 1] > xs[i] || (xs[i - 1] == xs[i] && ys[i - 1] > ys[i])) {
        return false;
      }
    }
    return true;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof ArMapPoints p
        && p.size == size
        && Arrays.equals(xs, 0, size, p.xs, 0, size)
        && Arrays.equals(ys, 0, size, p.ys, 0, size);
  }

  @Override
  public int hashCode() {
    int h = size;
    for (int i = 0; i < size; i++) {
      h = 31 * (31 * h + xs[i]) + ys[i];
    }
    return h;
  }

  @Override
  public String toString() {
    return "ArMapPoints[" + size + " points]";
  }
}
