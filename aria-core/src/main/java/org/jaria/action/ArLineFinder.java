package org.jaria.action;

import java.util.ArrayList;
import java.util.List;
import org.jaria.range.LaserScan;

/**
 * Finds straight lines in a laser scan (ARIA's {@code ArLineFinder}, with its own method): the
 * scan's points are split where consecutive points are far apart, each run is split recursively at
 * the point farthest from the chord while that point is off by more than the allowed distance, and
 * a line is fitted (least squares) to each piece. Pieces with too few points or too short are
 * dropped. Lines come out in sweep order, and neighbouring lines share the point where they meet,
 * so a corner is where two consecutive lines cross.
 *
 * <p>Not thread-safe; one action uses one finder.
 */
public class ArLineFinder {

  /** Gap between consecutive points that separates runs when none is set, mm. */
  public static final double DEFAULT_BREAK_DIST = 300;

  private double maxDistBetweenPoints;
  private double maxDistFromLine = 30;
  private int minPointsInLine = 3;
  private double minLineLength = 75;

  /** A finder with ARIA's default tolerances (30 mm off the line, 3 points, 75 mm). */
  public ArLineFinder() {}

  /**
   * Sets the largest gap between consecutive points of one line, mm; 0 (the default) uses {@link
   * #DEFAULT_BREAK_DIST}.
   */
  public void setMaxDistBetweenPoints(double mm) {
    maxDistBetweenPoints = mm;
  }

  /** Sets how far a point may be from its line before the line is split, mm (default 30). */
  public void setLineValidParams(double maxDistFromLine) {
    this.maxDistFromLine = maxDistFromLine;
  }

  /** Sets the fewest points (default 3) and shortest length (default 75 mm) a line may have. */
  public void setLineFilteringParams(int minPointsInLine, double minLineLength) {
    this.minPointsInLine = minPointsInLine;
    this.minLineLength = minLineLength;
  }

  /** The lines in {@code scan}, in sweep order. */
  public List<ArLineFinderSegment> getLines(LaserScan scan) {
    int n = scan.getNumPoints();
    double[] xs = new double[n];
    double[] ys = new double[n];
    for (int i = 0; i < n; i++) {
      xs[i] = scan.getX(i);
      ys[i] = scan.getY(i);
    }
    return getLines(xs, ys, n);
  }

  /** The lines through the first {@code n} points (xs[i], ys[i]), taken in order. */
  public List<ArLineFinderSegment> getLines(double[] xs, double[] ys, int n) {
    List<ArLineFinderSegment> out = new ArrayList<>();
    double gap = maxDistBetweenPoints > 0 ? maxDistBetweenPoints : DEFAULT_BREAK_DIST;
    int start = 0;
    for (int i = 1; i <= n; i++) {
      if (i == n || Math.hypot(xs[i] - xs[i - 1], ys[i] - ys[i - 1]) > gap) {
        split(xs, ys, start, i - 1, out, 0);
        start = i;
      }
    }
    return out;
  }

  private void split(
      double[] xs, double[] ys, int a, int b, List<ArLineFinderSegment> out, int depth) {
    if (b - a + 1 < 2) {
      return;
    }
    double dx = xs[b] - xs[a];
    double dy = ys[b] - ys[a];
    double len = Math.hypot(dx, dy);
    int worst = -1;
    double worstDist = 0;
    for (int i = a + 1; i < b; i++) {
      double d =
          len == 0
              ? Math.hypot(xs[i] - xs[a], ys[i] - ys[a])
              : Math.abs(dx * (ys[i] - ys[a]) - dy * (xs[i] - xs[a])) / len;
      if (d > worstDist) {
        worstDist = d;
        worst = i;
      }
    }
    // Depth is bounded by the number of points; the guard only protects against a pathological
    // stack on huge scans.
    if (worst > 0 && worstDist > maxDistFromLine && depth < 64) {
      split(xs, ys, a, worst, out, depth + 1);
      split(xs, ys, worst, b, out, depth + 1);
      return;
    }
    if (b - a + 1 < minPointsInLine) {
      return;
    }
    ArLineFinderSegment s = fit(xs, ys, a, b);
    if (s.getLength() >= minLineLength) {
      out.add(s);
    }
  }

  /** A least-squares line through points a..b, cut at the projections of the end points. */
  private static ArLineFinderSegment fit(double[] xs, double[] ys, int a, int b) {
    int n = b - a + 1;
    double mx = 0;
    double my = 0;
    for (int i = a; i <= b; i++) {
      mx += xs[i];
      my += ys[i];
    }
    mx /= n;
    my /= n;
    double sxx = 0;
    double syy = 0;
    double sxy = 0;
    for (int i = a; i <= b; i++) {
      double ex = xs[i] - mx;
      double ey = ys[i] - my;
      sxx += ex * ex;
      syy += ey * ey;
      sxy += ex * ey;
    }
    double theta = 0.5 * Math.atan2(2 * sxy, sxx - syy);
    double ux = Math.cos(theta);
    double uy = Math.sin(theta);
    // Orient the direction from the first point to the last.
    if ((xs[b] - xs[a]) * ux + (ys[b] - ys[a]) * uy < 0) {
      ux = -ux;
      uy = -uy;
    }
    double t1 = (xs[a] - mx) * ux + (ys[a] - my) * uy;
    double t2 = (xs[b] - mx) * ux + (ys[b] - my) * uy;
    return new ArLineFinderSegment(mx + t1 * ux, my + t1 * uy, mx + t2 * ux, my + t2 * uy, n);
  }
}
