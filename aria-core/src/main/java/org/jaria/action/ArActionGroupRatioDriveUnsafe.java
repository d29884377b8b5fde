package org.jaria.action;

import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;

/**
 * Keyboard, joystick and robot-joystick driving through one {@link ArActionRatioInput} with no
 * protection against collisions (ARIA's {@code ArActionGroupRatioDriveUnsafe}).
 */
public class ArActionGroupRatioDriveUnsafe extends ArActionGroup {

  private final ArActionRatioInput input = new ArActionRatioInput();
  private final ArRatioInputKeydrive keydrive;
  private final ArRatioInputJoydrive joydrive;
  private final ArRatioInputRobotJoydrive robotJoydrive;

  /** The group with a keyboard and no desktop joystick. */
  public ArActionGroupRatioDriveUnsafe(ArRobot robot, ArKeyHandler keyHandler) {
    this(robot, keyHandler, new ArJoyHandler());
  }

  /** The group reading {@code keyHandler}, {@code joyHandler} and the robot's joystick. */
  public ArActionGroupRatioDriveUnsafe(
      ArRobot robot, ArKeyHandler keyHandler, ArJoyHandler joyHandler) {
    super(robot);
    addAction(input, 50);
    keydrive = new ArRatioInputKeydrive(robot, input, keyHandler);
    joydrive = new ArRatioInputJoydrive(robot, input, joyHandler);
    robotJoydrive = new ArRatioInputRobotJoydrive(robot, input);
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
