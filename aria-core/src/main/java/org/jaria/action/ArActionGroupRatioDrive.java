package org.jaria.action;

import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;

/**
 * Keyboard, joystick and robot-joystick driving through one {@link ArActionRatioInput}, with
 * decelerating limiters against collisions (ARIA's {@code ArActionGroupRatioDrive}): the ratio
 * input at 50, then "DeceleratingLimiterForward" (40) and "DeceleratingLimiterBackward" (39), which
 * brake as hard as needed below the input's gentle deceleration requests. The inputs are an {@link
 * ArRatioInputKeydrive} (25), an {@link ArRatioInputJoydrive} (50) and an {@link
 * ArRatioInputRobotJoydrive} (75).
 */
public class ArActionGroupRatioDrive extends ArActionGroup {

  private final ArActionRatioInput input = new ArActionRatioInput();
  private final ArRatioInputKeydrive keydrive;
  private final ArRatioInputJoydrive joydrive;
  private final ArRatioInputRobotJoydrive robotJoydrive;
  private final ArActionDeceleratingLimiter forward =
      new ArActionDeceleratingLimiter(
          "DeceleratingLimiterForward", ArActionDeceleratingLimiter.LimiterType.FORWARDS);
  private final ArActionDeceleratingLimiter backward =
      new ArActionDeceleratingLimiter(
          "DeceleratingLimiterBackward", ArActionDeceleratingLimiter.LimiterType.BACKWARDS);

  /** The group with a keyboard and no desktop joystick. */
  public ArActionGroupRatioDrive(ArRobot robot, ArKeyHandler keyHandler) {
    this(robot, keyHandler, new ArJoyHandler());
  }

  /** The group reading {@code keyHandler}, {@code joyHandler} and the robot's joystick. */
  public ArActionGroupRatioDrive(ArRobot robot, ArKeyHandler keyHandler, ArJoyHandler joyHandler) {
    super(robot);
    addAction(input, 50);
    keydrive = new ArRatioInputKeydrive(robot, input, keyHandler);
    joydrive = new ArRatioInputJoydrive(robot, input, joyHandler);
    robotJoydrive = new ArRatioInputRobotJoydrive(robot, input);
    addAction(forward, 40);
    addAction(backward, 39);
  }

  /** The ratio input action. */
  public ArActionRatioInput getActionRatioInput() {
    return input;
  }

  /** The keyboard input. */
  public ArRatioInputKeydrive getKeydrive() {
    return keydrive;
  }

  /** The desktop-joystick input. */
  public ArRatioInputJoydrive getJoydrive() {
    return joydrive;
  }

  /** The robot-joystick input. */
  public ArRatioInputRobotJoydrive getRobotJoydrive() {
    return robotJoydrive;
  }
}
