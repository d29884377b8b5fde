package org.jaria.geom;

/**
 * A rigid 2-D transform (rotation then translation), ARIA's {@code ArTransform}.
 *
 * <p>Two uses: {@link #ofPose(ArPose)} maps points from a robot's local frame (x forward, y left)
 * into the frame the pose is given in; {@link #between(ArPose, ArPose)} maps a pose in one frame to
 * the same physical pose in another, which is how a localized pose is laid over raw odometry.
 * Immutable.
 */
public final class ArTransform {

  /** The transform that changes nothing. */
  public static final ArTransform IDENTITY = new ArTransform(0, 0, 0);

  private final double tx;
  private final double ty;
  private final double thDeg;
  private final double cos;
  private final double sin;

  private ArTransform(double tx, double ty, double thDeg) {
    this.tx = tx;
    this.ty = ty;
    this.thDeg = ArMath.fixAngle(thDeg);
    double r = Math.toRadians(thDeg);
    this.cos = Math.cos(r);
    this.sin = Math.sin(r);
  }

  /** The transform from the local frame of {@code pose} into the frame {@code pose} is in. */
  public static ArTransform ofPose(ArPose pose) {
    return new ArTransform(pose.x(), pose.y(), pose.th());
  }

  /**
   * The transform that takes {@code from} onto {@code to}: {@code between(a, b).doTransform(a)}
   * equals {@code b}, and every other pose moves rigidly with it.
   */
  public static ArTransform between(ArPose from, ArPose to) {
    double dth = ArMath.subAngle(to.th(), from.th());
    double r = Math.toRadians(dth);
    double c = Math.cos(r);
    double s = Math.sin(r);
    double tx = to.x() - (c * from.x() - s * from.y());
    double ty = to.y() - (s * from.x() + c * from.y());
    return new ArTransform(tx, ty, dth);
  }

  /** Applies the transform to a pose. */
  public ArPose doTransform(ArPose p) {
    return new ArPose(
        cos * p.x() - sin * p.y() + tx, sin * p.x() + cos * p.y() + ty, p.th() + thDeg);
  }

  /** Transformed x of the point (x, y); with {@link #transformY} avoids allocating in hot loops. */
  public double transformX(double x, double y) {
    return cos * x - sin * y + tx;
  }

  /** Transformed y of the point (x, y). */
  public double transformY(double x, double y) {
    return sin * x + cos * y + ty;
  }

  /** The rotation part, degrees. */
  public double getTh() {
    return thDeg;
  }

  /** The inverse transform. */
  public ArTransform inverse() {
    // R^-1 = R^T; t' = -R^T t
    double ix = -(cos * tx + sin * ty);
    double iy = -(-sin * tx + cos * ty);
    return new ArTransform(ix, iy, -thDeg);
  }

  /** This transform applied after {@code first}. */
  public ArTransform compose(ArTransform first) {
    ArPose p = doTransform(new ArPose(first.tx, first.ty, first.thDeg));
    return new ArTransform(p.x(), p.y(), p.th());
  }

  @Override
  public String toString() {
    return String.format(
        java.util.Locale.ROOT, "ArTransform[t=(%.1f, %.1f), th=%.2f°]", tx, ty, thDeg);
  }
}
