package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * A group for driving the robot from program input, with limiters against collisions (ARIA's {@code
 * ArActionGroupInput}): the table-sensor limiter (100), "Speed Limiter Near" (stop 300 mm, slow 600
 * mm, 250 mm/s; 90), "Speed Limiter Far" (300 mm, 1100 mm, 400 mm/s; 89), the backwards limiter
 * (80), and an {@link ArActionInput} (70) set through this group's methods.
 */
public class ArActionGroupInput extends ArActionGroup {

  private final ArActionInput input = new ArActionInput();

  /** Adds the actions to {@code robot}. */
  public ArActionGroupInput(ArRobot robot) {
    super(robot);
    addAction(new ArActionLimiterTableSensor(), 100);
    addAction(new ArActionLimiterForwards("Speed Limiter Near", 300, 600, 250), 90);
    addAction(new ArActionLimiterForwards("Speed Limiter Far", 300, 1100, 400), 89);
    addAction(new ArActionLimiterBackwards(), 80);
    addAction(input, 70);
  }

  /** Asks for this velocity, mm/s. */
  public void setVel(double vel) {
    input.setVel(vel);
  }

  /** Asks for this rotational velocity, deg/s. */
  public void setRotVel(double rotVel) {
    input.setRotVel(rotVel);
  }

  /** Asks for this absolute heading, degrees. */
  public void setHeading(double heading) {
    input.setHeading(heading);
  }

  /** Asks once for a change of heading, degrees. */
  public void deltaHeadingFromCurrent(double delta) {
    input.deltaHeadingFromCurrent(delta);
  }

  /** Stops asking for anything. */
  public void clear() {
    input.clear();
  }

  /** The input action. */
  public ArActionInput getActionInput() {
    return input;
  }
}
