package org.jaria.action;

/**
 * Drives as told from outside (ARIA's {@code ArActionInput}): a program, a GUI or a network command
 * sets a velocity and one way of rotating — a rotational velocity, a change of heading from the
 * current one, or an absolute heading — and the action asks for them every cycle until told
 * otherwise or {@link #clear()}ed. A change of heading is asked for once. Setters may be called
 * from any thread.
 */
public class ArActionInput extends ArAction {

  private enum RotRegime {
    NONE,
    ROTVEL,
    DELTAHEADING,
    SETHEADING
  }

  private final ArActionDesired desired = new ArActionDesired();
  private boolean usingVel;
  private double velSet;
  private RotRegime rotRegime = RotRegime.NONE;
  private double rotVal;

  /** "Input". */
  public ArActionInput() {
    this("Input");
  }

  /** An input action with a name. */
  public ArActionInput(String name) {
    super(name, "Inputs vel and heading");
  }

  /** Asks for this velocity, mm/s, from now on. */
  public void setVel(double vel) {
    locked(
        () -> {
          usingVel = true;
          velSet = vel;
        });
  }

  /** Asks for this rotational velocity, deg/s, from now on. */
  public void setRotVel(double rotVel) {
    locked(
        () -> {
          rotRegime = RotRegime.ROTVEL;
          rotVal = rotVel;
        });
  }

  /** Asks once for a change of heading of {@code delta} degrees from the current heading. */
  public void deltaHeadingFromCurrent(double delta) {
    locked(
        () -> {
          rotRegime = RotRegime.DELTAHEADING;
          rotVal = delta;
        });
  }

  /** Asks for this absolute heading, degrees, from now on. */
  public void setHeading(double heading) {
    locked(
        () -> {
          rotRegime = RotRegime.SETHEADING;
          rotVal = heading;
        });
  }

  /** Stops asking for anything. */
  public void clear() {
    locked(
        () -> {
          usingVel = false;
          rotRegime = RotRegime.NONE;
        });
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    if (usingVel) {
      desired.setVel(velSet);
    }
    switch (rotRegime) {
      case ROTVEL -> desired.setRotVel(rotVal);
      case DELTAHEADING -> {
        desired.setDeltaHeading(rotVal);
        // Asked for once: afterwards hold the heading reached.
        rotVal = 0;
      }
      case SETHEADING -> desired.setHeading(rotVal);
      case NONE -> {}
    }
    return desired;
  }
}
