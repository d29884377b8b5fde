package org.jaria.geom;

/** A line segment between two points, mm. Immutable. */
public record ArLineSegment(double x1, double y1, double x2, double y2) {

  /** A segment between two poses' points. */
  public ArLineSegment(ArPose a, ArPose b) {
    this(a.x(), a.y(), b.x(), b.y());
  }

  /** Length, mm. */
  public double length() {
    return Math.hypot(x2 - x1, y2 - y1);
  }

  /** The first end point. */
  public ArPose getEndPoint1() {
    return new ArPose(x1, y1);
  }

  /** The second end point. */
  public ArPose getEndPoint2() {
    return new ArPose(x2, y2);
  }

  /** Shortest distance from the point (px, py) to this segment. */
  public double getDistToLine(double px, double py) {
    double dx = x2 - x1;
    double dy = y2 - y1;
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : ((px - x1) * dx + (py - y1) * dy) / len2;
    t = ArMath.clamp(t, 0, 1);
    return Math.hypot(x1 + t * dx - px, y1 + t * dy - py);
  }

  /** Whether this segment crosses or touches {@code o}. */
  public boolean intersects(ArLineSegment o) {
    double d1 = cross(o.x1, o.y1, o.x2, o.y2, x1, y1);
    double d2 = cross(o.x1, o.y1, o.x2, o.y2, x2, y2);
    double d3 = cross(x1, y1, x2, y2, o.x1, o.y1);
    double d4 = cross(x1, y1, x2, y2, o.x2, o.y2);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
      return true;
    }
    return (d1 == 0 && onSegment(o, x1, y1))
        || (d2 == 0 && onSegment(o, x2, y2))
        || (d3 == 0 && onSegment(this, o.x1, o.y1))
        || (d4 == 0 && onSegment(this, o.x2, o.y2));
  }

  private static double cross(double ax, double ay, double bx, double by, double px, double py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  }

  private static boolean onSegment(ArLineSegment s, double px, double py) {
    return px >= Math.min(s.x1, s.x2)
        && px <= Math.max(s.x1, s.x2)
        && py >= Math.min(s.y1, s.y2)
        && py <= Math.max(s.y1, s.y2);
  }
}
