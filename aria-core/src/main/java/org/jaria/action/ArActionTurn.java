package org.jaria.action;

import org.jaria.range.ArRangeBuffer;
import org.jaria.robot.ArRobot;

/**
 * Turns when the robot has slowed down (ARIA's {@code ArActionTurn}). Meant to sit below limiter
 * actions: when they have slowed the robot below the start speed, it turns, by an amount that grows
 * to the full turn amount as the speed falls to the full-turn speed. It picks the side away from
 * the closest obstacle within 3 m ahead (left if there is none) and keeps turning that way until
 * the robot speeds up again. With limiters this makes a simple wander behaviour.
 */
public class ArActionTurn extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double speedStart;
  private volatile double speedFull;
  private volatile double turnAmount;
  private int turning;

  /** "turn" with ARIA's defaults: starts at 200 mm/s, full turn at 100 mm/s, 15°. */
  public ArActionTurn() {
    this("turn", 200, 100, 15);
  }

  /**
   * A turn action.
   *
   * @param name the action's name
   * @param speedStartTurn velocity below which turning starts, mm/s
   * @param speedFullTurn velocity below which the full amount is turned, mm/s
   * @param turnAmount degrees turned per cycle at most
   */
  public ArActionTurn(String name, double speedStartTurn, double speedFullTurn, double turnAmount) {
    super(name, "Turns the robot depending on actions by higher priority actions.");
    this.speedStart = speedStartTurn;
    this.speedFull = speedFullTurn;
    this.turnAmount = turnAmount;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    desired.reset();
    double vel = robot.getVel();
    if (vel > speedStart) {
      turning = 0;
      return null;
    }
    double amount;
    if (vel < speedFull) {
      amount = turnAmount;
    } else {
      amount = (speedStart - vel) / (speedStart - speedFull) * turnAmount;
    }
    if (turning == 0) {
      ArRangeBuffer.Closest c = RobotSensing.closestPolar(robot, -90, 90);
      if (c != null && c.distance() < 3000) {
        turning = c.angle() > 0 ? -1 : 1;
      } else {
        turning = 1;
      }
    }
    desired.setDeltaHeading(amount * turning);
    return desired;
  }
}
