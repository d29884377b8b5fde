package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * Limits rotation when something is inside the robot's radius (ARIA's {@code ArActionLimiterRot}):
 * turning in place with an obstacle that close would sweep the robot's corners into it. When the
 * check is on (it is off by default) and the closest reading on either side is nearer than the
 * robot's radius, it sets the maximum rotational velocity to the in-radius speed (0 or less: no
 * rotation).
 */
public class ArActionLimiterRot extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private volatile boolean checkRadius;
  private volatile double inRadiusSpeed;

  /** "limitRot" with ARIA's defaults: the radius check off. */
  public ArActionLimiterRot() {
    this("limitRot");
  }

  /** A rotation limiter with ARIA's defaults (check off, in-radius speed 0). */
  public ArActionLimiterRot(String name) {
    super(name, "Applies a limit to rotation if there are sensor readings in the radius");
    setParameters(false, 0);
  }

  /**
   * Sets the parameters.
   *
   * @param checkRadius whether to check for readings inside the robot's radius at all
   * @param inRadiusSpeed maximum rotational velocity then, deg/s (0 or less: none)
   */
  public void setParameters(boolean checkRadius, double inRadiusSpeed) {
    this.checkRadius = checkRadius;
    this.inRadiusSpeed = inRadiusSpeed;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (!checkRadius) {
      return null;
    }
    ArRobot robot = getRobot();
    double left = RobotSensing.polarDistance(robot, 0, 179.999);
    double right = RobotSensing.polarDistance(robot, -179.999, 0);
    double dist = Math.min(left, right);
    desired.reset();
    if (dist < robot.getRobotRadius()) {
      desired.setMaxRotVel(Math.max(0, inRadiusSpeed));
      return desired;
    }
    return null;
  }
}
