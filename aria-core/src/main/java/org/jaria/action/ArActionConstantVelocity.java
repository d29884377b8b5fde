package org.jaria.action;

/**
 * Drives straight ahead at a constant velocity (ARIA's {@code ArActionConstantVelocity}): every
 * cycle it asks for its velocity and no change of heading, at full strength. Put it below avoidance
 * actions so that they can steer it around obstacles.
 */
public class ArActionConstantVelocity extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double velocity;

  /** "Constant Velocity" at 400 mm/s, ARIA's defaults. */
  public ArActionConstantVelocity() {
    this("Constant Velocity", 400);
  }

  /**
   * A constant-velocity action.
   *
   * @param name the action's name
   * @param velocity the velocity to drive at, mm/s
   */
  public ArActionConstantVelocity(String name, double velocity) {
    super(name, "Sets the robot to travel straight at a constant velocity.");
    this.velocity = velocity;
  }

  /** The velocity asked for, mm/s. */
  public double getVelocity() {
    return velocity;
  }

  /** Sets the velocity to ask for, mm/s. */
  public void setVelocity(double velocity) {
    this.velocity = velocity;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    desired.setVel(velocity);
    desired.setDeltaHeading(0);
    return desired;
  }
}
