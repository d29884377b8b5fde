package org.jaria.arnl.mcl;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSensorReading;

/**
 * A laser scan for the Monte Carlo filter: each beam is a sensor reading with a zero-width cone, so
 * the sonar's sensor model becomes a laser likelihood field (each echo looked up once in the field,
 * its beam checked for walls it would have passed through). The filter itself is shared.
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
   * @param every use every n-th beam (1: all)
   */
  public static SonarScan prepare(
      double[] anglesDeg,
      double[] ranges,
      ArPose mount,
      ArPose encoderNow,
      double maxRange,
      int every) {
    List<ArSensorReading> readings = new ArrayList<>(ranges.length);
    for (int i = 0; i < ranges.length; i += Math.max(1, every)) {
      readings.add(
          new ArSensorReading(
              (int) Math.round(ranges[i]),
              0,
              0,
              mount.x(),
              mount.y(),
              mount.th() + anglesDeg[i],
              encoderNow,
              encoderNow,
              0,
              0));
    }
    return SonarScan.prepare(readings, encoderNow, MIN_RANGE, maxRange, 0, 1);
  }
}
