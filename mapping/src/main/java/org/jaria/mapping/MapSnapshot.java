package org.jaria.mapping;

import org.jaria.geom.ArPose;

/**
 * The map while it is being built, for drawing it live: the points seen so far (one per 50 mm cell,
 * placed by the current pose estimates) and the path driven. A snapshot does not change when the
 * builder goes on.
 */
public final class MapSnapshot {

  private final int[] xs;
  private final int[] ys;
  private final double[] pathX;
  private final double[] pathY;
  private final ArPose pose;

  MapSnapshot(int[] xs, int[] ys, double[] pathX, double[] pathY, ArPose pose) {
    this.xs = xs;
    this.ys = ys;
    this.pathX = pathX;
    this.pathY = pathY;
    this.pose = pose;
  }

  /** Number of points. */
  public int size() {
    return xs.length;
  }

  /** X of point {@code i}, mm. */
  public int x(int i) {
    return xs[i];
  }

  /** Y of point {@code i}, mm. */
  public int y(int i) {
    return ys[i];
  }

  /** Number of poses on the path. */
  public int pathSize() {
    return pathX.length;
  }

  /** X of pose {@code i} of the path (in the order driven), mm. */
  public double pathX(int i) {
    return pathX[i];
  }

  /** Y of pose {@code i} of the path, mm. */
  public double pathY(int i) {
    return pathY[i];
  }

  /** The latest pose. */
  public ArPose pose() {
    return pose;
  }
}
