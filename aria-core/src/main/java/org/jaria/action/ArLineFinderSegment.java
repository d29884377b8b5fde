package org.jaria.action;

import org.jaria.geom.ArPose;

/**
 * A straight piece of wall found in a laser scan by {@link ArLineFinder} (ARIA's {@code
 * ArLineFinderSegment}): its end points in global coordinates, in sweep order (end point 1 was
 * scanned first), and how many scan points it was fitted to.
 *
 * @param x1 global x of the first end point, mm
 * @param y1 global y of the first end point, mm
 * @param x2 global x of the second end point, mm
 * @param y2 global y of the second end point, mm
 * @param numPoints number of scan points on the line
 */
public record ArLineFinderSegment(double x1, double y1, double x2, double y2, int numPoints) {

  /** The first end point (scanned first). */
  public ArPose getEndPoint1() {
    return new ArPose(x1, y1);
  }

  /** The second end point. */
  public ArPose getEndPoint2() {
    return new ArPose(x2, y2);
  }

  /** Direction from the first end point to the second, degrees. */
  public double getLineAngle() {
    return Math.toDegrees(Math.atan2(y2 - y1, x2 - x1));
  }

  /** Length, mm. */
  public double getLength() {
    return Math.hypot(x2 - x1, y2 - y1);
  }

  /**
   * Where the infinite lines through this segment and {@code o} cross, or null if they are
   * parallel.
   */
  public ArPose intersection(ArLineFinderSegment o) {
    double dx1 = x2 - x1;
    double dy1 = y2 - y1;
    double dx2 = o.x2 - o.x1;
    double dy2 = o.y2 - o.y1;
    double den = dx1 * dy2 - dy1 * dx2;
    if (Math.abs(den) < 1e-9 * (Math.hypot(dx1, dy1) * Math.hypot(dx2, dy2) + 1e-12)) {
      return null;
    }
    double t = ((o.x1 - x1) * dy2 - (o.y1 - y1) * dx2) / den;
    return new ArPose(x1 + t * dx1, y1 + t * dy1);
  }
}
