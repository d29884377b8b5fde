package org.jaria.action;

/**
 * Sets the maximum speeds, accelerations and decelerations (ARIA's {@code
 * ArActionMovementParameters}). Each parameter left at 0 is not set. Limits combine by taking the
 * most restrictive value, so this action can lower the limits the robot uses whatever its priority.
 * It can be switched off and on with {@link #disable()} / {@link #enable()} independently of
 * activation, or enabled for a single cycle.
 */
public class ArActionMovementParameters extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private final boolean overrideFaster;
  private boolean enabled = true;
  private boolean enableOnce;
  private double maxVel;
  private double maxNegVel;
  private double transAccel;
  private double transDecel;
  private double maxRotVel;
  private double rotAccel;
  private double rotDecel;

  /** "MovementParameters" with nothing set yet. */
  public ArActionMovementParameters() {
    this("MovementParameters", true);
  }

  /**
   * A movement-parameters action.
   *
   * @param name the action's name
   * @param overrideFaster kept for ARIA compatibility (ARIA stores but never uses it)
   */
  public ArActionMovementParameters(String name, boolean overrideFaster) {
    super(name, "Sets all the max vel and accels/decels");
    this.overrideFaster = overrideFaster;
  }

  /** The (unused) override-faster flag. */
  public boolean getOverrideFaster() {
    return overrideFaster;
  }

  /**
   * Sets the parameters; 0 leaves one unset.
   *
   * @param maxVel maximum forward velocity, mm/s
   * @param maxNegVel maximum backward velocity, mm/s, as a positive number
   * @param transAccel translational acceleration, mm/s²
   * @param transDecel translational deceleration, mm/s²
   * @param rotVelMax maximum rotational velocity, deg/s
   * @param rotAccel rotational acceleration, deg/s²
   * @param rotDecel rotational deceleration, deg/s²
   */
  public void setParameters(
      double maxVel,
      double maxNegVel,
      double transAccel,
      double transDecel,
      double rotVelMax,
      double rotAccel,
      double rotDecel) {
    locked(
        () -> {
          this.maxVel = maxVel;
          this.maxNegVel = maxNegVel;
          this.transAccel = transAccel;
          this.transDecel = transDecel;
          this.maxRotVel = rotVelMax;
          this.rotAccel = rotAccel;
          this.rotDecel = rotDecel;
        });
  }

  /** Enables the action (separately from activation). */
  public void enable() {
    locked(() -> enabled = true);
  }

  /** Enables the action for the next cycle only. */
  public void enableOnce() {
    locked(() -> enableOnce = true);
  }

  /** Disables the action (separately from activation). */
  public void disable() {
    locked(() -> enabled = false);
  }

  /** Whether the action is enabled. */
  public boolean isEnabled() {
    return lockedGet(() -> enabled);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    desired.reset();
    if (!enabled && !enableOnce) {
      return null;
    }
    enableOnce = false;
    if (Math.abs(maxVel) >= 1) {
      desired.setMaxVel(maxVel);
    }
    if (Math.abs(maxNegVel) >= 1) {
      desired.setMaxNegVel(-maxNegVel);
    }
    if (Math.abs(transAccel) >= 1) {
      desired.setTransAccel(transAccel);
    }
    if (Math.abs(transDecel) >= 1) {
      desired.setTransDecel(transDecel);
    }
    if (Math.abs(maxRotVel) >= 1) {
      desired.setMaxRotVel(maxRotVel);
    }
    if (Math.abs(rotAccel) >= 1) {
      desired.setRotAccel(rotAccel);
    }
    if (Math.abs(rotDecel) >= 1) {
      desired.setRotDecel(rotDecel);
    }
    return desired;
  }
}
