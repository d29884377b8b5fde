package org.jaria.action;

/**
 * One channel of an {@link ArActionDesired}: a desired value and how strongly (0..1) it is wanted.
 *
 * <p>Two ways of combining channels exist, as in ARIA. Ordinary channels (velocity, heading) are
 * weighted by strength. Limit channels (maximum speeds, accelerations) set with "allow override"
 * take the most restrictive value instead: the smallest, or for decelerations and the maximum
 * backwards speed, the largest.
 */
public final class ArActionDesiredChannel {

  /** No strength: the channel is unused. */
  public static final double NO_STRENGTH = 0.0;

  /** Smallest strength that counts as wanting something. */
  public static final double MIN_STRENGTH = 0.000001;

  /** Full strength: nothing of lower priority can change this channel any more. */
  public static final double MAX_STRENGTH = 1.0;

  private final boolean overrideDoesLessThan;
  private double desired;
  private double strength;
  private boolean allowOverride;
  private boolean rejected;
  private double desiredTotal;
  private double strengthTotal;

  /**
   * A channel; {@code overrideDoesLessThan} says whether "most restrictive" means smallest (speeds,
   * accelerations) or largest (decelerations, the backwards limit).
   */
  ArActionDesiredChannel(boolean overrideDoesLessThan) {
    this.overrideDoesLessThan = overrideDoesLessThan;
    reset();
  }

  /**
   * Sets the desire. Strengths above 1 are cut to 1; below {@link #MIN_STRENGTH} they become 0.
   *
   * @param allowOverride combine with others by taking the most restrictive value
   */
  void setDesired(double value, double desiredStrength, boolean allowOverride) {
    if (!Double.isFinite(value) || Double.isNaN(desiredStrength)) {
      // A NaN or infinite speed would reach the robot as garbage: drop the desire, and let
      // sanityCheck name the action that asked for it.
      this.desired = 0;
      this.strength = NO_STRENGTH;
      this.allowOverride = allowOverride;
      this.rejected = true;
      return;
    }
    this.desired = value;
    this.strength = desiredStrength;
    this.allowOverride = allowOverride;
    if (strength > MAX_STRENGTH) {
      strength = MAX_STRENGTH;
    }
    if (strength < MIN_STRENGTH) {
      strength = NO_STRENGTH;
    }
  }

  /** The desired value. */
  public double getDesired() {
    return desired;
  }

  /** The strength 0..1. */
  public double getStrength() {
    return strength;
  }

  /** Whether this channel combines by taking the most restrictive value. */
  public boolean getAllowOverride() {
    return allowOverride;
  }

  /** Whether the last value set was NaN or infinite (and so dropped); clears the flag. */
  boolean takeRejected() {
    boolean r = rejected;
    rejected = false;
    return r;
  }

  /** Clears the desire. */
  void reset() {
    rejected = false;
    desired = 0;
    strength = NO_STRENGTH;
    allowOverride = true;
  }

  void copyFrom(ArActionDesiredChannel o) {
    desired = o.desired;
    strength = o.strength;
    allowOverride = o.allowOverride;
  }

  /**
   * Merges a lower-priority channel into this one: it may only fill the strength this channel has
   * left, and a limit channel keeps the most restrictive value.
   */
  void merge(ArActionDesiredChannel other) {
    double otherStrength = other.strength;
    double oldStrength = strength;
    if (strength + otherStrength > MAX_STRENGTH) {
      otherStrength = MAX_STRENGTH - strength;
    }
    strength = strength + otherStrength;
    allowOverride = allowOverride && other.allowOverride;
    if (allowOverride && strength >= MIN_STRENGTH) {
      if (oldStrength >= MIN_STRENGTH && other.strength >= MIN_STRENGTH) {
        desired = mostRestrictive(desired, other.desired);
      } else if (other.strength >= MIN_STRENGTH) {
        desired = other.desired;
      }
    } else if (strength >= MIN_STRENGTH) {
      desired = ((oldStrength * desired) + (other.desired * otherStrength)) / strength;
    }
  }

  private double mostRestrictive(double a, double b) {
    return overrideDoesLessThan ? Math.min(a, b) : Math.max(a, b);
  }

  void startAverage() {
    desiredTotal = desired * strength;
    strengthTotal = strength;
  }

  void addAverage(ArActionDesiredChannel other) {
    allowOverride = allowOverride && other.allowOverride;
    if (allowOverride) {
      // ARIA tests this channel's own strength here, which stays 0 while averaging, so the last
      // limit of a priority level won over stricter ones; the running total fixes that.
      if (strengthTotal >= MIN_STRENGTH && other.strength >= MIN_STRENGTH) {
        desired = mostRestrictive(desired, other.desired);
      } else if (other.strength >= MIN_STRENGTH) {
        desired = other.desired;
      }
    }
    desiredTotal += other.desired * other.strength;
    strengthTotal += other.strength;
  }

  void endAverage() {
    if (strengthTotal < MIN_STRENGTH) {
      strength = NO_STRENGTH;
      return;
    }
    if (!allowOverride) {
      desired = desiredTotal / strengthTotal;
    }
    strength = Math.min(strengthTotal, MAX_STRENGTH);
  }

  /** Raises the value to {@code bound} if below it (when the channel is in use). */
  boolean checkLowerBound(double bound) {
    if (strength >= MIN_STRENGTH && Math.round(desired) < bound) {
      desired = bound;
      return true;
    }
    return false;
  }

  /** Lowers the value to {@code bound} if above it (when the channel is in use). */
  boolean checkUpperBound(double bound) {
    if (strength >= MIN_STRENGTH && Math.round(desired) > bound) {
      desired = bound;
      return true;
    }
    return false;
  }

  @Override
  public String toString() {
    return strength < MIN_STRENGTH
        ? "-"
        : String.format(java.util.Locale.ROOT, "%.1f@%.2f", desired, strength);
  }
}
