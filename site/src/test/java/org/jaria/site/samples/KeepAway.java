package org.jaria.site.samples;

import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;

// tag::action[]
/** Backs away from anything closer than {@code mm} in front; wants nothing otherwise. */
public class KeepAway extends ArAction {

  private final double mm;
  private final ArActionDesired desired = new ArActionDesired();

  public KeepAway(double mm) {
    super("keep away", "backs off from obstacles ahead");
    this.mm = mm;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    double ahead = getRobot().checkRangeDevicesCurrentPolar(-30, 30);
    if (ahead >= mm) {
      return null; // nothing to say: lower priorities decide
    }
    desired.reset();
    desired.setVel(-150); // strength 1.0: no lower-priority action can change the speed
    desired.setDeltaHeading(0);
    return desired;
  }
}
// end::action[]
