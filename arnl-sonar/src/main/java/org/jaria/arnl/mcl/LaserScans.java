package org.jaria.arnl.mcl;

import org.jaria.geom.ArPose;

/**
 * A laser scan for the Monte Carlo filter: each beam that returned an echo becomes one end point in
 * the robot's frame, looked up once in the likelihood field ({@link LaserLikelihood}). The filter
 * itself is the one sonar localization uses.
 */
public final class LaserScans {

  private LaserScans() {}

  /** Echoes shorter than this are taken as the robot's own body, mm. */
  public static final double MIN_RANGE = 50;

  /**
   * Prepares a scan taken at odometry pose {@code encoderNow} (the scan's end points are in the
   * robot's frame at that pose, so the pose itself is not needed here; the parameter keeps the
   * signature of the sonar's preparation).
   *
   * @param anglesDeg beam directions relative to the laser, degrees
   * @param ranges beam ranges, mm (at or beyond {@code maxRange}: no echo, not used)
   * @param mount the laser's pose on the robot
   * @param every use every n-th beam (1: all); ARNL too thins a scan, since neighbouring beams
   *     carry nearly the same information
   */
  public static SonarScan prepare(
      double[] anglesDeg,
      double[] ranges,
      ArPose mount,
      ArPose encoderNow,
      double maxRange,
      int every) {
    int step = Math.max(1, every);
    int cap = (ranges.length + step - 1) / step;
    double[] ex = new double[cap];
    double[] ey = new double[cap];
    double[] fx = new double[cap];
    double[] fy = new double[cap];
    double[] axis = new double[cap];
    double[] range = new double[cap];
    double mth = Math.toRadians(mount.th());
    int used = 0;
    int ignored = 0;
    for (int i = 0; i < ranges.length; i += step) {
      double r = ranges[i];
      if (!(r >= MIN_RANGE && r < maxRange)) {
        ignored++;
        continue;
      }
      double a = mth + Math.toRadians(anglesDeg[i]);
      fx[used] = mount.x();
      fy[used] = mount.y();
      axis[used] = a;
      range[used] = r;
      ex[used] = mount.x() + r * Math.cos(a);
      ey[used] = mount.y() + r * Math.sin(a);
      used++;
    }
    return SonarScan.ofBeams(ex, ey, fx, fy, axis, range, used, ignored);
  }
}
