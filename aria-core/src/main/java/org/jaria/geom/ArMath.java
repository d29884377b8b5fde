package org.jaria.geom;

/** Angle and distance helpers (ARIA's {@code ArMath}). Angles are in degrees unless named Rad. */
public final class ArMath {

  private ArMath() {}

  /** Converts degrees to radians. */
  public static double degToRad(double deg) {
    return Math.toRadians(deg);
  }

  /** Converts radians to degrees. */
  public static double radToDeg(double rad) {
    return Math.toDegrees(rad);
  }

  /** Reduces an angle to the range (−180, 180]. */
  public static double fixAngle(double deg) {
    if (deg > 180 || deg <= -180) {
      deg = deg % 360;
      if (deg > 180) {
        deg -= 360;
      } else if (deg <= -180) {
        deg += 360;
      }
    }
    return deg;
  }

  /** {@code a + b}, reduced to (−180, 180]. */
  public static double addAngle(double a, double b) {
    return fixAngle(a + b);
  }

  /** {@code a − b}, reduced to (−180, 180]: the signed turn from b to a. */
  public static double subAngle(double a, double b) {
    return fixAngle(a - b);
  }

  /** Euclidean distance between two points. */
  public static double distanceBetween(double x1, double y1, double x2, double y2) {
    return Math.hypot(x2 - x1, y2 - y1);
  }

  /** Heading in degrees from (x1, y1) towards (x2, y2). */
  public static double angleBetween(double x1, double y1, double x2, double y2) {
    return Math.toDegrees(Math.atan2(y2 - y1, x2 - x1));
  }

  /** Rounds half away from zero to an int, like ARIA's {@code ArMath::roundInt}. */
  public static int roundInt(double v) {
    return (int) (v < 0 ? v - 0.5 : v + 0.5);
  }

  /** Whether two doubles differ by less than {@code epsilon}. */
  public static boolean compareFloats(double a, double b, double epsilon) {
    return Math.abs(a - b) < epsilon;
  }

  /** Clamps {@code v} into [lo, hi]. */
  public static double clamp(double v, double lo, double hi) {
    return v < lo ? lo : (v > hi ? hi : v);
  }
}
