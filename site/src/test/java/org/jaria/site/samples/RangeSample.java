package org.jaria.site.samples;

import org.jaria.range.ArBumpers;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/** Range devices and their queries (the range devices guide). */
public final class RangeSample {

  private RangeSample() {}

  /** The closest obstacles around the robot, mm from its centre. */
  public record Around(double ahead, double leftLately, double inBox, int sonar3) {}

  /** Adds the sonar and the bumpers to {@code robot}. */
  public static void addDevices(ArRobot robot) {
    // tag::add[]
    robot.addRangeDevice(new ArSonarDevice()); // the sonar ring(s) the robot's parameters list
    robot.addRangeDevice(new ArBumpers()); // a pressed bumper becomes an obstacle point
    // end::add[]
  }

  /** What the devices see now. */
  public static Around look(ArRobot robot) {
    // tag::queries[]
    // The closest reading in the 60 degrees ahead (0 = straight ahead, + = left), mm:
    double ahead = robot.checkRangeDevicesCurrentPolar(-30, 30);
    // What the sonar has seen on the left recently, even if no sonar points there now:
    double leftLately = robot.checkRangeDevicesCumulativePolar(60, 120);
    // The closest reading in a box 1 m ahead and 60 cm wide (robot frame: x ahead, y left):
    double inBox = robot.checkRangeDevicesCurrentBox(0, -300, 1000, 300);
    // One sonar's last range, mm (on a P3-DX sonar 0 points left, 3 and 4 almost ahead):
    int sonar3 = robot.getSonarRange(3);
    // end::queries[]
    return new Around(ahead, leftLately, inBox, sonar3);
  }
}
