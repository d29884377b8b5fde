package org.jaria.arnl;

import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;

/**
 * Limits the robot's speed while localization is not certain (ARNL's {@code
 * ArActionSlowDownWhenNotCertain}): after a failed update, during global localization, or before
 * localization has started. A slower robot gives the localization more readings per metre to
 * recover with. It only sets maximum speeds; other actions still decide where to go.
 */
public class ArActionSlowDownWhenNotCertain extends ArAction {

  private final ArBaseLocalizationTask loc;
  private final ArActionDesired desired = new ArActionDesired();
  private volatile double slowSpeed = 150;
  private volatile double slowRotSpeed = 20;

  /** Slows down to 150 mm/s and 20 °/s while {@code loc} is not certain. */
  public ArActionSlowDownWhenNotCertain(ArBaseLocalizationTask loc) {
    super("slowDownWhenNotCertain", "slows down while localization is uncertain");
    this.loc = loc;
  }

  /** Sets the top speeds used while uncertain (mm/s, deg/s). */
  public void setSlowSpeeds(double mmPerSec, double degPerSec) {
    slowSpeed = Math.abs(mmPerSec);
    slowRotSpeed = Math.abs(degPerSec);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (loc.getLockState() == LockState.LOCKED) {
      return null;
    }
    desired.reset();
    desired.setMaxVel(slowSpeed);
    desired.setMaxNegVel(-slowSpeed);
    desired.setMaxRotVel(slowRotSpeed);
    return desired;
  }
}
