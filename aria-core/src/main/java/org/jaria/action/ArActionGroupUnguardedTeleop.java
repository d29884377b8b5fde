package org.jaria.action;

import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;

/**
 * A group for driving the robot by joystick and keyboard with no protection against collisions
 * (ARIA's {@code ArActionGroupUnguardedTeleop}): {@link ArActionJoydrive} (70, letting the keyboard
 * drive when no button is held) and {@link ArActionKeydrive} (69).
 */
public class ArActionGroupUnguardedTeleop extends ArActionGroup {

  private final ArActionJoydrive joydrive;
  private final ArActionKeydrive keydrive;

  /** The group with a keyboard and no joystick. */
  public ArActionGroupUnguardedTeleop(ArRobot robot, ArKeyHandler keyHandler) {
    this(robot, keyHandler, new ArJoyHandler());
  }

  /** The group reading {@code keyHandler} and {@code joyHandler}. */
  public ArActionGroupUnguardedTeleop(
      ArRobot robot, ArKeyHandler keyHandler, ArJoyHandler joyHandler) {
    super(robot);
    joydrive = new ArActionJoydrive(joyHandler);
    joydrive.setStopIfNoButtonPressed(false);
    addAction(joydrive, 70);
    keydrive = new ArActionKeydrive(keyHandler);
    addAction(keydrive, 69);
  }

  /** Uses the joystick's throttle to scale the speed between these values, mm/s. */
  public void setThrottleParams(int lowSpeed, int highSpeed) {
    joydrive.setThrottleParams(lowSpeed, highSpeed);
  }

  /** The joystick action. */
  public ArActionJoydrive getJoydrive() {
    return joydrive;
  }

  /** The keyboard action. */
  public ArActionKeydrive getKeydrive() {
    return keydrive;
  }
}
