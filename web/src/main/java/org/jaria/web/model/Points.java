package org.jaria.web.model;

import java.util.Arrays;

/**
 * An immutable list of points in the plane, x and y in millimetres, kept as one packed {@code
 * float} array (x0, y0, x1, y1, ...) so that thousands of particles or laser end points cost one
 * array, not thousands of objects. Two {@code Points} are equal when they hold the same values.
 */
public final class Points {

  /** No points. */
  public static final Points EMPTY = new Points(new float[0]);

  private final float[] xy;

  private Points(float[] xy) {
    this.xy = xy;
  }

  /**
   * Points from packed coordinates (copied).
   *
   * @param xy x0, y0, x1, y1, ... in millimetres
   * @throws IllegalArgumentException if the array has an odd length
   */
  public static Points of(float... xy) {
    if (xy.length % 2 != 0) {
      throw new IllegalArgumentException(
          "points come in x, y pairs; got " + xy.length + " numbers");
    }
    return xy.length == 0 ? EMPTY : new Points(xy.clone());
  }

  /** Takes {@code xy} without copying it: the caller must not change it afterwards. */
  static Points wrap(float[] xy) {
    return xy.length == 0 ? EMPTY : new Points(xy);
  }

  /** A builder for {@code capacity} points (it grows if more are added). */
  public static Builder builder(int capacity) {
    return new Builder(capacity);
  }

  /** The number of points. */
  public int size() {
    return xy.length / 2;
  }

  /** Whether there are none. */
  public boolean isEmpty() {
    return xy.length == 0;
  }

  /** The x of point {@code i}, mm. */
  public float x(int i) {
    return xy[2 * i];
  }

  /** The y of point {@code i}, mm. */
  public float y(int i) {
    return xy[2 * i + 1];
  }

  /** A copy of the packed coordinates. */
  public float[] toArray() {
    return xy.clone();
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof Points p && Arrays.equals(xy, p.xy);
  }

  @Override
  public int hashCode() {
    return Arrays.hashCode(xy);
  }

  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder("Points[");
    int shown = Math.min(size(), 4);
    for (int i = 0; i < shown; i++) {
      sb.append(i == 0 ? "" : ", ").append('(').append(x(i)).append(", ").append(y(i)).append(')');
    }
    return sb.append(size() > shown ? ", ... " + size() + " in all]" : "]").toString();
  }

  /** Collects points one by one; {@link #build()} hands over the array without a copy. */
  public static final class Builder {
    private float[] xy;
    private int n;

    private Builder(int capacity) {
      xy = new float[2 * Math.max(capacity, 1)];
    }

    /** Adds a point. */
    public Builder add(double x, double y) {
      if (n + 2 > xy.length) {
        xy = Arrays.copyOf(xy, 2 * xy.length);
      }
      xy[n++] = (float) x;
      xy[n++] = (float) y;
      return this;
    }

    /** The points added so far. */
    public Points build() {
      return wrap(n == xy.length ? xy : Arrays.copyOf(xy, n));
    }
  }
}
