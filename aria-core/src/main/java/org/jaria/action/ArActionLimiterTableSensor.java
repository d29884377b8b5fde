package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * Stops forward motion when a table-sensing IR sees something (ARIA's {@code
 * ArActionLimiterTableSensor}): sets the maximum velocity to 0 while either IR is triggered. It
 * does nothing on robots whose parameters do not declare table-sensing IRs.
 */
public class ArActionLimiterTableSensor extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();

  /** "TableSensorLimiter". */
  public ArActionLimiterTableSensor() {
    this("TableSensorLimiter");
  }

  /** A table-sensor limiter with a name. */
  public ArActionLimiterTableSensor(String name) {
    super(name, "Limits speed to 0 if a table is seen");
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    desired.reset();
    if (RobotSensing.hasTableSensingIR(robot)
        && (RobotSensing.isLeftTableSensingIRTriggered(robot)
            || RobotSensing.isRightTableSensingIRTriggered(robot))) {
      desired.setMaxVel(0);
      return desired;
    }
    return null;
  }
}
