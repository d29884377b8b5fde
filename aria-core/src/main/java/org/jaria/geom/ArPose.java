package org.jaria.geom;

/**
 * A position and heading in the plane: x and y in millimetres, th in degrees (counter-clockwise
 * from +x), always reduced to (−180, 180]. Immutable.
 *
 * <p>ARIA's getters ({@link #getX()} ...) are here so code ports unchanged; where ARIA would mutate
 * a pose ({@code setX}), use the {@code with...} methods, which return a new pose.
 */
public record ArPose(double x, double y, double th) {

  /** The origin facing +x. */
  public static final ArPose ORIGIN = new ArPose(0, 0, 0);

  /** Normalises the heading. */
  public ArPose {
    th = ArMath.fixAngle(th);
  }

  /** A pose with heading 0. */
  public ArPose(double x, double y) {
    this(x, y, 0);
  }

  /** X, mm. */
  public double getX() {
    return x;
  }

  /** Y, mm. */
  public double getY() {
    return y;
  }

  /** Heading, degrees in (−180, 180]. */
  public double getTh() {
    return th;
  }

  /** Heading in radians. */
  public double getThRad() {
    return Math.toRadians(th);
  }

  /** This pose with another x. */
  public ArPose withX(double newX) {
    return new ArPose(newX, y, th);
  }

  /** This pose with another y. */
  public ArPose withY(double newY) {
    return new ArPose(x, newY, th);
  }

  /** This pose with another heading. */
  public ArPose withTh(double newTh) {
    return new ArPose(x, y, newTh);
  }

  /** Distance to {@code other}, mm (headings ignored). */
  public double findDistanceTo(ArPose other) {
    return Math.hypot(other.x - x, other.y - y);
  }

  /** Squared distance to {@code other}; cheaper when only comparing. */
  public double squaredFindDistanceTo(ArPose other) {
    double dx = other.x - x;
    double dy = other.y - y;
    return dx * dx + dy * dy;
  }

  /** Direction from this pose's point to {@code other}'s point, degrees. */
  public double findAngleTo(ArPose other) {
    return ArMath.angleBetween(x, y, other.x, other.y);
  }

  /** Vector sum (x, y and heading added). */
  public ArPose plus(ArPose o) {
    return new ArPose(x + o.x, y + o.y, th + o.th);
  }

  /** Vector difference. */
  public ArPose minus(ArPose o) {
    return new ArPose(x - o.x, y - o.y, th - o.th);
  }

  /** Whether x, y and th are each within the given tolerances of {@code o}. */
  public boolean isNear(ArPose o, double distTolerance, double angleTolerance) {
    return findDistanceTo(o) <= distTolerance
        && Math.abs(ArMath.subAngle(th, o.th)) <= angleTolerance;
  }

  @Override
  public String toString() {
    return String.format(java.util.Locale.ROOT, "(%.1f, %.1f, %.1f°)", x, y, th);
  }
}
