package org.jaria.action;

import org.jaria.params.ArRobotParams;
import org.jaria.range.ArRangeBuffer;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * Queries the predefined actions need that {@link ArRobot} does not answer directly: the closest
 * reading with its direction, and the table-sensing IRs of PeopleBots.
 *
 * <p>ARIA returns −1 from its range-device queries when the robot has no range device at all, which
 * made several actions act as if an obstacle touched the robot. Here "nothing seen" is always a
 * large distance, with or without devices.
 */
final class RobotSensing {

  /** Distance meaning "nothing seen", mm. */
  static final double NOTHING = Double.MAX_VALUE;

  private RobotSensing() {}

  /**
   * The closest current reading of any range device in the sector from {@code startAngle}
   * counter-clockwise to {@code endAngle} (degrees, robot frame), or null if none.
   */
  static ArRangeBuffer.Closest closestPolar(ArRobot robot, double startAngle, double endAngle) {
    ArRangeBuffer.Closest best = null;
    for (ArRangeDevice d : robot.getRangeDeviceList()) {
      ArRangeBuffer.Closest c = d.currentReadingPolarDetail(startAngle, endAngle);
      if (c != null
          && c.distance() < d.getMaxRange()
          && (best == null || c.distance() < best.distance())) {
        best = c;
      }
    }
    return best;
  }

  /** Distance of the closest current reading in the sector, or {@link #NOTHING}. */
  static double polarDistance(ArRobot robot, double startAngle, double endAngle) {
    ArRangeBuffer.Closest c = closestPolar(robot, startAngle, endAngle);
    return c == null ? NOTHING : c.distance();
  }

  /**
   * Distance of the closest current reading in the robot-frame box, or {@link #NOTHING} (readings
   * at a device's maximum range count as nothing).
   */
  static double boxDistance(ArRobot robot, double x1, double y1, double x2, double y2) {
    double best = NOTHING;
    for (ArRangeDevice d : robot.getRangeDeviceList()) {
      ArRangeBuffer.Closest c = d.currentReadingBoxDetail(x1, y1, x2, y2);
      if (c != null && c.distance() < d.getMaxRange() && c.distance() < best) {
        best = c.distance();
      }
    }
    return best;
  }

  /** Whether the robot's parameters say it has table-sensing IRs. */
  static boolean hasTableSensingIR(ArRobot robot) {
    return robot.getRobotParams().haveTableSensingIR();
  }

  /**
   * Whether the left table-sensing IR sees something. The IRs are active-low: in the fourth IOpac
   * digital-input byte (bit 1) on robots with the new table-sensing IRs, else in the SIP's DIGIN
   * byte (bit 0).
   */
  static boolean isLeftTableSensingIRTriggered(ArRobot robot) {
    return tableIr(robot, 1, 0);
  }

  /** Whether the right table-sensing IR sees something (IOpac bit 0, or DIGIN bit 1). */
  static boolean isRightTableSensingIRTriggered(ArRobot robot) {
    return tableIr(robot, 0, 1);
  }

  private static boolean tableIr(ArRobot robot, int newBit, int oldBit) {
    ArRobotParams p = robot.getRobotParams();
    if (!p.haveTableSensingIR()) {
      return false;
    }
    if (p.haveNewTableSensingIR()) {
      return robot.getIODigInSize() > 3 && (robot.getIODigIn(3) & (1 << newBit)) == 0;
    }
    return (robot.getDigIn() & (1 << oldBit)) == 0;
  }
}
