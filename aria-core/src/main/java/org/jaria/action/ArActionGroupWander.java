package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * A group that makes the robot wander, avoiding obstacles (ARIA's {@code ArActionGroupWander}):
 * {@link ArActionBumpers} (100), {@link ArActionStallRecover} (90), an {@link ArActionAvoidFront}
 * "Avoid Front" (79) and an {@link ArActionConstantVelocity} "Constant Velocity" (50).
 */
public class ArActionGroupWander extends ArActionGroup {

  /** With ARIA's defaults: 400 mm/s forward, avoiding from 450 mm at 200 mm/s, turning 15°. */
  public ArActionGroupWander(ArRobot robot) {
    this(robot, 400, 450, 200, 15);
  }

  /**
   * A wander group.
   *
   * @param robot the robot
   * @param forwardVel cruising velocity, mm/s
   * @param avoidFrontDist distance from the robot's edge at which to avoid, mm
   * @param avoidVel velocity while avoiding, mm/s
   * @param avoidTurnAmt degrees to turn per cycle while avoiding
   */
  public ArActionGroupWander(
      ArRobot robot, int forwardVel, int avoidFrontDist, int avoidVel, int avoidTurnAmt) {
    super(robot);
    addAction(new ArActionBumpers(), 100);
    addAction(new ArActionStallRecover(), 90);
    addAction(new ArActionAvoidFront("Avoid Front", avoidFrontDist, avoidVel, avoidTurnAmt), 79);
    addAction(new ArActionConstantVelocity("Constant Velocity", forwardVel), 50);
  }
}
