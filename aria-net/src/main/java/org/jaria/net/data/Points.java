package org.jaria.net.data;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.NetEncodable;

/**
 * An immutable list of points in whole millimetres, optionally with headings in whole degrees:
 * range readings, a path, particles, a polygon. Kept as one primitive array (x, y[, th] per point)
 * so thousands of particles cost one allocation, and sent as one array of integers.
 */
public final class Points implements NetEncodable {

  /** No points. */
  public static final Points EMPTY = new Points(new int[0], 2);

  private final int[] values;
  private final int stride;

  private Points(int[] values, int stride) {
    this.values = values;
    this.stride = stride;
  }

  /** Points (x, y) from poses (headings dropped). */
  public static Points of(List<ArPose> poses) {
    return of(poses, false);
  }

  /** Points from poses, with their headings if {@code withHeadings}. */
  public static Points of(List<ArPose> poses, boolean withHeadings) {
    int stride = withHeadings ? 3 : 2;
    int[] v = new int[poses.size() * stride];
    int i = 0;
    for (ArPose p : poses) {
      v[i++] = ArMath.roundInt(p.getX());
      v[i++] = ArMath.roundInt(p.getY());
      if (withHeadings) {
        v[i++] = ArMath.roundInt(p.getTh());
      }
    }
    return new Points(v, stride);
  }

  /**
   * Points from a flat array (x, y[, th] per point), copied.
   *
   * @param stride 2 (x, y) or 3 (x, y, th)
   */
  public static Points ofFlat(int[] flat, int stride) {
    if ((stride != 2 && stride != 3) || flat.length % stride != 0) {
      throw new IllegalArgumentException(
          "a flat point array needs stride 2 or 3 and a multiple of it in length");
    }
    return new Points(flat.clone(), stride);
  }

  /** Number of points. */
  public int size() {
    return values.length / stride;
  }

  /** Whether the points carry headings. */
  public boolean hasHeadings() {
    return stride == 3;
  }

  /** x of point {@code i}, mm. */
  public int x(int i) {
    return values[i * stride];
  }

  /** y of point {@code i}, mm. */
  public int y(int i) {
    return values[i * stride + 1];
  }

  /** Heading of point {@code i}, degrees (0 without headings). */
  public int th(int i) {
    return stride == 3 ? values[i * stride + 2] : 0;
  }

  /** The points as poses. */
  public List<ArPose> toPoses() {
    List<ArPose> l = new ArrayList<>(size());
    for (int i = 0; i < size(); i++) {
      l.add(new ArPose(x(i), y(i), th(i)));
    }
    return l;
  }

  @Override
  public void write(ArNetPacket out) {
    out.arrayToBuf(2).intToBuf(stride).arrayToBuf(values.length);
    for (int v : values) {
      out.byte4ToBuf(v);
    }
  }

  /** Reads what {@link #write} wrote. */
  public static Points read(ArNetPacket in) {
    int n = Fields.begin(in, 2, "points");
    int stride = in.bufToInt();
    int[] v = new int[in.bufToArray()];
    for (int i = 0; i < v.length; i++) {
      v[i] = in.bufToByte4();
    }
    Fields.end(in, n, 2);
    if ((stride != 2 && stride != 3) || v.length % stride != 0) {
      throw new ArNetPacketException(
          "points with stride " + stride + " and " + v.length + " values");
    }
    return new Points(v, stride);
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof Points p && p.stride == stride && Arrays.equals(p.values, values);
  }

  @Override
  public int hashCode() {
    return 31 * stride + Arrays.hashCode(values);
  }

  @Override
  public String toString() {
    return "Points[" + size() + (stride == 3 ? " with headings]" : "]");
  }
}
