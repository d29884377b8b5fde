package org.jaria.arnl.plan;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;

/**
 * A path as a polyline of points (mm) with the distance along it to each point. Immutable; the
 * arrays are never exposed.
 */
public final class PlannedPath {

  private final double[] x;
  private final double[] y;
  private final double[] s;

  /** A path through the given points (at least one). */
  public PlannedPath(double[] xs, double[] ys) {
    if (xs.length == 0 || xs.length != ys.length) {
      throw new IllegalArgumentException("a path needs at least one point and as many x as y");
    }
    x = xs.clone();
    y = ys.clone();
    s = new double[x.length];
    for (int i = 1; i < x.length; i++) {
      s[i] = s[i - 1] + Math.hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
    }
  }

  /** Number of points. */
  public int size() {
    return x.length;
  }

  /** x of point i. */
  public double x(int i) {
    return x[i];
  }

  /** y of point i. */
  public double y(int i) {
    return y[i];
  }

  /** Distance along the path from the start to point i, mm. */
  public double distanceTo(int i) {
    return s[i];
  }

  /** Length, mm. */
  public double length() {
    return s[s.length - 1];
  }

  /**
   * The index of the point nearest (px, py) among points {@code from} .. {@code from + window} (so
   * that a path passing the same place twice is followed in order).
   */
  public int closestIndex(double px, double py, int from, int window) {
    int best = Math.max(0, Math.min(from, x.length - 1));
    double bestD = Double.MAX_VALUE;
    int end = Math.min(x.length - 1, best + window);
    for (int i = best; i <= end; i++) {
      double d = (x[i] - px) * (x[i] - px) + (y[i] - py) * (y[i] - py);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  }

  /** The index of the first point at least {@code dist} mm further along than point i. */
  public int indexAhead(int i, double dist) {
    double target = s[i] + dist;
    int k = i;
    while (k < x.length - 1 && s[k] < target) {
      k++;
    }
    return k;
  }

  /** Distance from (px, py) to the nearest segment among points from .. from+window, mm. */
  public double distanceToPath(double px, double py, int from, int window) {
    int a = Math.max(0, Math.min(from, x.length - 1));
    int b = Math.min(x.length - 1, a + window);
    if (a == b) {
      return Math.hypot(px - x[a], py - y[a]);
    }
    double best = Double.MAX_VALUE;
    for (int i = a; i < b; i++) {
      double dx = x[i + 1] - x[i];
      double dy = y[i + 1] - y[i];
      double len2 = dx * dx + dy * dy;
      double t = len2 > 0 ? ((px - x[i]) * dx + (py - y[i]) * dy) / len2 : 0;
      t = Math.max(0, Math.min(1, t));
      best = Math.min(best, Math.hypot(px - (x[i] + t * dx), py - (y[i] + t * dy)));
    }
    return best;
  }

  /**
   * Distance left to the end for someone at (px, py): to the nearest point of the path, then along
   * it, mm.
   */
  public double remainingFrom(double px, double py) {
    int i = closestIndex(px, py, 0, x.length);
    return Math.hypot(px - x[i], py - y[i]) + length() - s[i];
  }

  /** The points as poses (heading along the path). */
  public List<ArPose> toPoses() {
    List<ArPose> out = new ArrayList<>(x.length);
    for (int i = 0; i < x.length; i++) {
      int j = Math.min(i + 1, x.length - 1);
      int k = j == i ? Math.max(0, i - 1) : i;
      double th = j == k ? 0 : Math.toDegrees(Math.atan2(y[j] - y[k], x[j] - x[k]));
      out.add(new ArPose(x[i], y[i], th));
    }
    return out;
  }

  /** The smallest clearance along the path on {@code grid}, mm. */
  public double minClearance(CostGrid grid) {
    double best = Double.MAX_VALUE;
    for (int i = 0; i < x.length; i++) {
      best = Math.min(best, grid.clearanceAt(x[i], y[i]));
    }
    return best;
  }
}
