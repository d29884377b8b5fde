package org.jaria.sim.world;

/**
 * Small allocation-free geometry primitives shared by the spatial index and the footprints:
 * ray/segment and ray/disc intersection, segment/convex-polygon overlap, closest points.
 *
 * <p>Polygons are given as coordinate arrays with their vertices in counter-clockwise order.
 */
final class Geometry2d {

  /** Denominators smaller than this mean "parallel". */
  private static final double PARALLEL_EPS = 1e-12;

  private Geometry2d() {}

  /**
   * Distance along the ray (origin o, unit direction d) to the segment (a, b), or {@link
   * Double#POSITIVE_INFINITY} if the ray misses it. A ray parallel to the segment misses.
   */
  static double raySegment(
      double ox, double oy, double dx, double dy, double ax, double ay, double bx, double by) {
    double ex = bx - ax;
    double ey = by - ay;
    double denom = dx * ey - dy * ex;
    if (Math.abs(denom) < PARALLEL_EPS) {
      return Double.POSITIVE_INFINITY;
    }
    double px = ax - ox;
    double py = ay - oy;
    double t = (px * ey - py * ex) / denom;
    double s = (px * dy - py * dx) / denom;
    if (t < 0 || s < 0 || s > 1) {
      return Double.POSITIVE_INFINITY;
    }
    return t;
  }

  /** |cos| of the angle between the unit ray direction and the normal of segment (a, b). */
  static double cosIncidenceSegment(
      double dx, double dy, double ax, double ay, double bx, double by) {
    double ex = bx - ax;
    double ey = by - ay;
    double len = Math.sqrt(ex * ex + ey * ey);
    return len == 0 ? 1 : Math.abs(dx * ey - dy * ex) / len;
  }

  /**
   * Distance along the ray to the circle (c, r); 0 if the origin is inside the circle; {@link
   * Double#POSITIVE_INFINITY} if the ray misses.
   */
  static double rayDisc(
      double ox, double oy, double dx, double dy, double cx, double cy, double r) {
    double mx = ox - cx;
    double my = oy - cy;
    double c = mx * mx + my * my - r * r;
    if (c <= 0) {
      return 0;
    }
    double b = mx * dx + my * dy;
    if (b > 0) {
      return Double.POSITIVE_INFINITY;
    }
    double disc = b * b - c;
    if (disc < 0) {
      return Double.POSITIVE_INFINITY;
    }
    return -b - Math.sqrt(disc);
  }

  /** Whether (x, y) is inside or on the convex CCW polygon. */
  static boolean pointInConvex(double x, double y, double[] px, double[] py, int n) {
    for (int i = 0, j = n - 1; i < n; j = i++) {
      double cross = (px[i] - px[j]) * (y - py[j]) - (py[i] - py[j]) * (x - px[j]);
      if (cross < 0) {
        return false;
      }
    }
    return true;
  }

  /**
   * Clips segment (a, b) against the convex CCW polygon (Cyrus–Beck): on overlap writes the
   * parameters t0 ≤ t1 in [0, 1] of the part inside into {@code out} and returns true.
   */
  static boolean clipSegmentConvex(
      double ax, double ay, double bx, double by, double[] px, double[] py, int n, double[] out) {
    double t0 = 0;
    double t1 = 1;
    double dx = bx - ax;
    double dy = by - ay;
    for (int i = 0, j = n - 1; i < n; j = i++) {
      // Inward normal of a counter-clockwise edge: its left normal.
      double nx = -(py[i] - py[j]);
      double ny = px[i] - px[j];
      double num = (ax - px[j]) * nx + (ay - py[j]) * ny;
      double den = dx * nx + dy * ny;
      if (den == 0) {
        if (num < 0) {
          return false;
        }
      } else {
        double t = -num / den;
        if (den > 0) {
          t0 = Math.max(t0, t);
        } else {
          t1 = Math.min(t1, t);
        }
        if (t0 > t1) {
          return false;
        }
      }
    }
    out[0] = t0;
    out[1] = t1;
    return true;
  }

  /** Squared distance from (x, y) to segment (a, b). */
  static double distSqToSegment(double x, double y, double ax, double ay, double bx, double by) {
    double ex = bx - ax;
    double ey = by - ay;
    double len2 = ex * ex + ey * ey;
    double t = len2 == 0 ? 0 : ((x - ax) * ex + (y - ay) * ey) / len2;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    double qx = ax + t * ex - x;
    double qy = ay + t * ey - y;
    return qx * qx + qy * qy;
  }

  /** Whether the disc (c, r) overlaps the convex CCW polygon. */
  static boolean discOverlapsConvex(
      double cx, double cy, double r, double[] px, double[] py, int n) {
    if (pointInConvex(cx, cy, px, py, n)) {
      return true;
    }
    double r2 = r * r;
    for (int i = 0, j = n - 1; i < n; j = i++) {
      if (distSqToSegment(cx, cy, px[j], py[j], px[i], py[i]) <= r2) {
        return true;
      }
    }
    return false;
  }

  /** Whether two convex CCW polygons overlap (separating axis test on their edge normals). */
  static boolean convexOverlap(double[] ax, double[] ay, int an, double[] bx, double[] by, int bn) {
    return !hasSeparatingEdge(ax, ay, an, bx, by, bn) && !hasSeparatingEdge(bx, by, bn, ax, ay, an);
  }

  private static boolean hasSeparatingEdge(
      double[] ax, double[] ay, int an, double[] bx, double[] by, int bn) {
    for (int i = 0, j = an - 1; i < an; j = i++) {
      double ex = ax[i] - ax[j];
      double ey = ay[i] - ay[j];
      // Outward normal of a CCW polygon edge is (ey, -ex): B is separated if all its
      // vertices are on the outer side.
      boolean allOutside = true;
      for (int k = 0; k < bn; k++) {
        double side = ex * (by[k] - ay[j]) - ey * (bx[k] - ax[j]);
        if (side >= 0) {
          allOutside = false;
          break;
        }
      }
      if (allOutside) {
        return true;
      }
    }
    return false;
  }
}
