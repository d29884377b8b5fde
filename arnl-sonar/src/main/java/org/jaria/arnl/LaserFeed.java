package org.jaria.arnl;

import java.util.concurrent.TimeUnit;
import org.jaria.arnl.mcl.LaserScans;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.range.LaserScan;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;

/**
 * A laser as a {@link ScanFeed}: its newest complete scan, placed at the odometry pose the robot
 * had when the scan was taken.
 *
 * <p>Why that pose matters: a laser's scans arrive on their own schedule (a reader thread, or
 * packets after the SIP), and a scan placed at the odometry of a later moment is off by the
 * distance driven in between, along the direction of travel. Each {@link LaserScan} carries the
 * global pose of the sensor when it was taken, computed from the robot's pose at that moment; the
 * robot's encoder→global transform turns it back into that moment's odometry pose, and the scan's
 * end points are moved from there into the robot's frame at the update.
 */
final class LaserFeed implements ScanFeed {

  /** A scan older than this is not used to localize a robot standing still. */
  private static final long CURRENT_MAX_AGE_NANOS = TimeUnit.SECONDS.toNanos(3);

  private final ArRobot robot;
  private final LaserScanSource laser;
  private final ArPose mount;
  private final double maxRange;
  private final LocalizationParams params;

  /** The newest scan and the odometry pose it was taken at (written on the cycle thread). */
  private record Noted(LaserScan scan, ArPose encoderTaken, long when) {}

  private volatile Noted newest;

  // Cycle thread only.
  private LaserScan lastSeen;
  private boolean fresh;

  LaserFeed(
      ArRobot robot,
      LaserScanSource laser,
      ArPose mount,
      double maxRange,
      LocalizationParams params) {
    this.robot = robot;
    this.laser = laser;
    this.mount = mount;
    this.maxRange = maxRange;
    this.params = params;
  }

  @Override
  public void note() {
    LaserScan s = laser.getLaserScan();
    if (s == null || s == lastSeen) {
      return;
    }
    lastSeen = s;
    fresh = true;
    newest = new Noted(s, encoderPoseAt(s), robot.getClock().nanoTime());
  }

  /** The odometry pose of the robot when {@code s} was taken. */
  private ArPose encoderPoseAt(LaserScan s) {
    // The scan holds the sensor's global pose; the robot's is the mount's inverse from there.
    ArPose sensor = s.getSensorPose();
    ArPose robotGlobal =
        ArTransform.ofPose(sensor)
            .compose(ArTransform.ofPose(mount).inverse())
            .doTransform(ArPose.ORIGIN);
    return robot.getEncoderTransform().inverse().doTransform(robotGlobal);
  }

  @Override
  public SonarScan takeFresh(ArPose encoderNow) {
    Noted n = newest;
    if (!fresh || n == null) {
      return LaserScans.prepare(new double[0], new double[0], mount, encoderNow, maxRange, 1);
    }
    fresh = false;
    return prepare(n, encoderNow);
  }

  @Override
  public SonarScan current(ArPose encoderNow) {
    Noted n = newest;
    if (n == null || robot.getClock().nanoTime() - n.when() > CURRENT_MAX_AGE_NANOS) {
      LaserScan s = laser.getLaserScan();
      if (s == null) {
        return LaserScans.prepare(new double[0], new double[0], mount, encoderNow, maxRange, 1);
      }
      // Not noted yet (the task was just made): the robot has hardly moved since.
      n = new Noted(s, encoderPoseAt(s), robot.getClock().nanoTime());
    }
    return prepare(n, encoderNow);
  }

  private SonarScan prepare(Noted n, ArPose encoderNow) {
    LaserScan s = n.scan();
    int count = s.size();
    double[] angles = new double[count];
    double[] ranges = new double[count];
    for (int i = 0; i < count; i++) {
      angles[i] = s.getAngle(i);
      ranges[i] = s.getRange(i);
    }
    double range = Math.min(maxRange, params.laserMaxRange.getDouble());
    return LaserScans.prepare(
        angles, ranges, mount, n.encoderTaken(), encoderNow, range, params.laserBeamStep.getInt());
  }

  @Override
  public String what() {
    return "laser scan";
  }
}
