package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * Turns away from walls beside the robot (ARIA's {@code ArActionAvoidSide}): obstacles at an angle
 * that the front-avoidance actions do not see. It checks the sectors 60°–120° (left) and −120°–−60°
 * (right); if the closest reading on a side is nearer than the obstacle distance (from the robot's
 * edge), it stops and turns away by the turn amount. When both sides are clear again it asks once
 * more for no turn, to end the manoeuvre.
 *
 * <p>Difference from ARIA: ARIA never reset its "turning" flag, so after the first wall it asked
 * for "no turn" at full strength every cycle forever, silencing every lower-priority action that
 * steers. Here the manoeuvre ends when the sides are clear.
 */
public class ArActionAvoidSide extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double obsDist;
  private volatile double turnAmount;
  private boolean turning;

  /** "Avoid side" with ARIA's defaults: 300 mm, 5°. */
  public ArActionAvoidSide() {
    this("Avoid side", 300, 5);
  }

  /**
   * An avoid-side action.
   *
   * @param name the action's name
   * @param obstacleDistance distance from the robot's edge at which to start avoiding, mm
   * @param turnAmount degrees to turn per cycle
   */
  public ArActionAvoidSide(String name, double obstacleDistance, double turnAmount) {
    super(name, "Avoids side obstacles, ie walls");
    this.obsDist = obstacleDistance;
    this.turnAmount = turnAmount;
  }

  /** Distance at which avoiding starts, mm. */
  public double getObstacleDistance() {
    return obsDist;
  }

  /** Degrees turned per cycle. */
  public double getTurnAmount() {
    return turnAmount;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    double leftDist = RobotSensing.polarDistance(robot, 60, 120) - robot.getRobotRadius();
    double rightDist = RobotSensing.polarDistance(robot, -120, -60) - robot.getRobotRadius();
    desired.reset();
    if (leftDist < obsDist) {
      desired.setDeltaHeading(-turnAmount);
      desired.setVel(0);
      turning = true;
    } else if (rightDist < obsDist) {
      desired.setDeltaHeading(turnAmount);
      desired.setVel(0);
      turning = true;
    } else if (turning) {
      desired.setDeltaHeading(0);
      turning = false;
    } else {
      return null;
    }
    return desired;
  }
}
