package org.jaria.laser.log;

import java.util.List;
import java.util.Objects;
import org.jaria.geom.ArPose;

/**
 * The header of a laser scan log: format version, where the laser sits on the robot and what it
 * sweeps.
 *
 * @param version the {@code version:} line (ARIA 3 writes 4; 0 if the log has none)
 * @param laserPose the laser's mounting pose on the robot (x ahead, y left of the centre, mm; th
 *     degrees counter-clockwise)
 * @param laserZ the laser's height above the floor, mm (0 if the log does not say)
 * @param firstAngle angle of the first reading relative to the laser, degrees
 * @param lastAngle angle of the last reading relative to the laser, degrees
 * @param readingCount readings per sweep (0 if the log does not say)
 * @param laserName the laser's name ({@code lms2xx_1}, {@code sim_lms2xx_1}, ...), may be empty
 * @param locationTypes the robot poses each scan carries ({@code robot}, {@code robotGlobal}, ...)
 */
public record ScanLogHeader(
    int version,
    ArPose laserPose,
    double laserZ,
    double firstAngle,
    double lastAngle,
    int readingCount,
    String laserName,
    List<String> locationTypes) {

  /** The version ARIA 3's {@code ArLaserLogger} writes. */
  public static final int ARIA_VERSION = 4;

  /** Checks and copies the values. */
  public ScanLogHeader {
    Objects.requireNonNull(laserPose, "laserPose");
    Objects.requireNonNull(laserName, "laserName");
    locationTypes = List.copyOf(locationTypes);
    if (readingCount < 0) {
      throw new IllegalArgumentException("a laser has no negative reading count: " + readingCount);
    }
  }

  /**
   * The header ARIA writes for a laser mounted at {@code laserPose} sweeping {@code firstAngle} to
   * {@code lastAngle} in {@code readingCount} readings (version 4, poses {@code robot
   * robotGlobal}).
   */
  public static ScanLogHeader of(
      ArPose laserPose, double firstAngle, double lastAngle, int readingCount, String laserName) {
    return new ScanLogHeader(
        ARIA_VERSION,
        laserPose,
        0,
        firstAngle,
        lastAngle,
        readingCount,
        laserName,
        List.of("robot", "robotGlobal"));
  }

  /** Angle between two readings, degrees (0 if the log gives fewer than two readings). */
  public double increment() {
    return readingCount < 2 ? 0 : (lastAngle - firstAngle) / (readingCount - 1);
  }
}
