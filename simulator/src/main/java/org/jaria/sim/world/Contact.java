package org.jaria.sim.world;

/**
 * Where a robot's footprint touches something, filled in place by collision queries: the touching
 * point nearest to the robot's centre (it decides which bumper segment closes).
 */
public final class Contact {

  /** Contact point x, mm (world frame). */
  public double x;

  /** Contact point y, mm (world frame). */
  public double y;

  /** Squared distance from the query centre to the contact point. */
  public double distSq = Double.POSITIVE_INFINITY;

  /** What was touched. */
  public RayHit.HitKind kind = RayHit.HitKind.NONE;

  /** Number of the robot touched (only for {@link RayHit.HitKind#ROBOT}), else -1. */
  public int robot = -1;

  /** Whether anything was touched. */
  public boolean touched() {
    return kind != RayHit.HitKind.NONE;
  }

  /** Forgets the previous result. */
  public void reset() {
    distSq = Double.POSITIVE_INFINITY;
    kind = RayHit.HitKind.NONE;
    robot = -1;
  }

  /**
   * Keeps ({@code px}, {@code py}) if it is nearer to ({@code cx}, {@code cy}) than the current.
   */
  void offer(double px, double py, double cx, double cy, RayHit.HitKind k, int robotIndex) {
    double ddx = px - cx;
    double ddy = py - cy;
    double d = ddx * ddx + ddy * ddy;
    if (d < distSq) {
      distSq = d;
      x = px;
      y = py;
      kind = k;
      robot = robotIndex;
    }
  }
}
