package org.jaria.arnl.mcl;

import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;

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
   * Prepares a scan taken at odometry pose {@code encoderNow}.
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
    return prepare(anglesDeg, ranges, mount, encoderNow, encoderNow, maxRange, every);
  }

  /**
   * Prepares a scan taken at odometry pose {@code encoderTaken} for an update at odometry pose
   * {@code encoderNow}: the end points are placed in the robot's frame at {@code encoderNow}, so a
   * scan that is older than the update is not misplaced by the distance driven since.
   */
  public static SonarScan prepare(
      double[] anglesDeg,
      double[] ranges,
      ArPose mount,
      ArPose encoderTaken,
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
    // The sensor's pose in the robot's frame at encoderNow.
    ArTransform toNow = ArTransform.ofPose(encoderNow).inverse();
    ArPose sensor = toNow.compose(ArTransform.ofPose(encoderTaken)).doTransform(mount);
    double sth = Math.toRadians(sensor.th());
    int used = 0;
    int ignored = 0;
    for (int i = 0; i < ranges.length; i += step) {
      double r = ranges[i];
      if (!(r >= MIN_RANGE && r < maxRange)) {
        ignored++;
        continue;
      }
      double a = sth + Math.toRadians(anglesDeg[i]);
      fx[used] = sensor.x();
      fy[used] = sensor.y();
      axis[used] = a;
      range[used] = r;
      ex[used] = sensor.x() + r * Math.cos(a);
      ey[used] = sensor.y() + r * Math.sin(a);
      used++;
    }
    return SonarScan.ofBeams(ex, ey, fx, fy, axis, range, used, ignored);
  }
}
