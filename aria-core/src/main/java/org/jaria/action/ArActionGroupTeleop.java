package org.jaria.action;

import org.jaria.input.ArJoyHandler;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;

/**
 * A group for driving the robot by joystick and keyboard with limiters against collisions (ARIA's
 * {@code ArActionGroupTeleop}): the table-sensor limiter (100), "Speed Limiter Near" (300 mm, 600
 * mm, 250 mm/s; 90), "Speed Limiter Far" (300 mm, 1100 mm, 400 mm/s; 89), the backwards limiter
 * (80), {@link ArActionJoydrive} (70, letting others drive when no button is held) and {@link
 * ArActionKeydrive} (69).
 */
public class ArActionGroupTeleop extends ArActionGroup {

  private final ArActionJoydrive joydrive;
  private final ArActionKeydrive keydrive;

  /** The group with a keyboard and no joystick. */
  public ArActionGroupTeleop(ArRobot robot, ArKeyHandler keyHandler) {
    this(robot, keyHandler, new ArJoyHandler());
  }

  /** The group reading {@code keyHandler} and {@code joyHandler}. */
  public ArActionGroupTeleop(ArRobot robot, ArKeyHandler keyHandler, ArJoyHandler joyHandler) {
    super(robot);
    addAction(new ArActionLimiterTableSensor(), 100);
    addAction(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250), 90);
    addAction(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400), 89);
    addAction(new ArActionLimiterBackwards(), 80);
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
