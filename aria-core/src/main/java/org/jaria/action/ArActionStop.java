package org.jaria.action;

/**
 * Stops the robot: asks for zero velocity and no change of heading, at full strength (ARIA's {@code
 * ArActionStop}). Put it above the other actions, or activate it exclusively ({@link
 * ArActionGroupStop}), to hold the robot still.
 */
public class ArActionStop extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();

  /** A stop action called "stop". */
  public ArActionStop() {
    this("stop");
  }

  /** A stop action with a name. */
  public ArActionStop(String name) {
    super(name, "Stops the robot");
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    desired.setVel(0);
    desired.setDeltaHeading(0);
    return desired;
  }
}
