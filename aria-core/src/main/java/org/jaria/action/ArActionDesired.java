package org.jaria.action;

import org.jaria.geom.ArMath;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What an action wants the robot to do this cycle (ARIA's {@code ArActionDesired}).
 *
 * <p>Each kind of command is a separate channel with its own strength from 0 to 1: translational
 * velocity, change of heading (or an absolute heading, turned into a change when the resolver
 * runs), rotational velocity, and the limits — maximum forward and backward speeds, maximum
 * rotational speed (overall and per direction), and accelerations and decelerations. An action sets
 * only the channels it cares about; the resolver combines the desires of all actions.
 *
 * <p>Heading and rotational velocity are alternatives: if a delta heading is set, a rotational
 * velocity is ignored, and the other way round. Lateral channels of omnidirectional robots are not
 * modelled (Pioneers cannot move sideways).
 */
public class ArActionDesired {

  private static final Logger log = LoggerFactory.getLogger(ArActionDesired.class);

  /** No strength: the channel is unused. */
  public static final double NO_STRENGTH = ArActionDesiredChannel.NO_STRENGTH;

  /** Smallest strength that counts. */
  public static final double MIN_STRENGTH = ArActionDesiredChannel.MIN_STRENGTH;

  /** Full strength. */
  public static final double MAX_STRENGTH = ArActionDesiredChannel.MAX_STRENGTH;

  private final ArActionDesiredChannel vel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel maxVel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel maxNegVel = new ArActionDesiredChannel(false);
  private final ArActionDesiredChannel transAccel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel transDecel = new ArActionDesiredChannel(false);
  private final ArActionDesiredChannel rotVel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel deltaHeading = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel maxRotVel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel maxRotVelPos = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel maxRotVelNeg = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel rotAccel = new ArActionDesiredChannel(true);
  private final ArActionDesiredChannel rotDecel = new ArActionDesiredChannel(false);

  /** Every channel: the three motion channels first, then the limits (merged uniformly). */
  private final ArActionDesiredChannel[] all = {
    vel,
    rotVel,
    deltaHeading,
    maxVel,
    maxNegVel,
    transAccel,
    transDecel,
    maxRotVel,
    maxRotVelPos,
    maxRotVelNeg,
    rotAccel,
    rotDecel
  };

  private static final int FIRST_LIMIT = 3;

  /** Names of the channels in {@link #all}, for log messages. */
  private static final String[] CHANNEL_NAMES = {
    "vel",
    "rotVel",
    "deltaHeading",
    "maxVel",
    "maxNegVel",
    "transAccel",
    "transDecel",
    "maxRotVel",
    "maxRotVelPos",
    "maxRotVelNeg",
    "rotAccel",
    "rotDecel"
  };

  private double heading;
  private double headingStrength;
  private boolean headingSet;
  private boolean headingRejected;

  // ------------------------------------------------------------------ setters

  /** Translational velocity, mm/s, at full strength. */
  public void setVel(double mmPerSec) {
    setVel(mmPerSec, MAX_STRENGTH);
  }

  /** Translational velocity, mm/s. */
  public void setVel(double mmPerSec, double strength) {
    vel.setDesired(mmPerSec, strength, false);
  }

  /** Change of heading, degrees (+ counter-clockwise), at full strength. */
  public void setDeltaHeading(double degrees) {
    setDeltaHeading(degrees, MAX_STRENGTH);
  }

  /** Change of heading, degrees. Ignored if a rotational velocity is already set. */
  public void setDeltaHeading(double degrees, double strength) {
    deltaHeading.setDesired(degrees, strength, false);
  }

  /** Absolute heading, degrees, at full strength. */
  public void setHeading(double degrees) {
    setHeading(degrees, MAX_STRENGTH);
  }

  /**
   * Absolute heading, degrees. The resolver turns it into a change of heading from the robot's
   * heading ({@link #accountForRobotHeading}).
   */
  public void setHeading(double degrees, double strength) {
    if (!Double.isFinite(degrees) || Double.isNaN(strength)) {
      headingRejected = true;
      return;
    }
    heading = degrees;
    headingStrength = strength;
    headingSet = true;
  }

  /** Rotational velocity, deg/s, at full strength. */
  public void setRotVel(double degPerSec) {
    setRotVel(degPerSec, MAX_STRENGTH);
  }

  /** Rotational velocity, deg/s. Ignored if a heading is already set. */
  public void setRotVel(double degPerSec, double strength) {
    rotVel.setDesired(degPerSec, strength, false);
  }

  /** Maximum forward velocity, mm/s; the slowest of all actions wins. */
  public void setMaxVel(double mmPerSec) {
    setMaxVel(mmPerSec, MAX_STRENGTH, true);
  }

  /** Maximum forward velocity; {@code useSlowest} false averages by strength instead. */
  public void setMaxVel(double mmPerSec, double strength, boolean useSlowest) {
    maxVel.setDesired(mmPerSec, strength, useSlowest);
  }

  /** Maximum backward velocity (a negative number, mm/s); the slowest wins. */
  public void setMaxNegVel(double mmPerSec) {
    setMaxNegVel(mmPerSec, MAX_STRENGTH, true);
  }

  /** Maximum backward velocity. */
  public void setMaxNegVel(double mmPerSec, double strength, boolean useSlowest) {
    maxNegVel.setDesired(mmPerSec, strength, useSlowest);
  }

  /** Translational acceleration, mm/s²; the gentlest wins. */
  public void setTransAccel(double mmPerSec2) {
    setTransAccel(mmPerSec2, MAX_STRENGTH, true);
  }

  /** Translational acceleration. */
  public void setTransAccel(double mmPerSec2, double strength, boolean useSlowest) {
    transAccel.setDesired(mmPerSec2, strength, useSlowest);
  }

  /** Translational deceleration, mm/s²; the hardest wins. */
  public void setTransDecel(double mmPerSec2) {
    setTransDecel(mmPerSec2, MAX_STRENGTH, true);
  }

  /** Translational deceleration. */
  public void setTransDecel(double mmPerSec2, double strength, boolean useFastest) {
    transDecel.setDesired(mmPerSec2, strength, useFastest);
  }

  /** Maximum rotational velocity, deg/s; the slowest wins. */
  public void setMaxRotVel(double degPerSec) {
    setMaxRotVel(degPerSec, MAX_STRENGTH, true);
  }

  /** Maximum rotational velocity. */
  public void setMaxRotVel(double degPerSec, double strength, boolean useSlowest) {
    maxRotVel.setDesired(degPerSec, strength, useSlowest);
  }

  /** Maximum counter-clockwise rotational velocity, deg/s. */
  public void setMaxRotVelPos(double degPerSec) {
    setMaxRotVelPos(degPerSec, MAX_STRENGTH, true);
  }

  /** Maximum counter-clockwise rotational velocity. */
  public void setMaxRotVelPos(double degPerSec, double strength, boolean useSlowest) {
    maxRotVelPos.setDesired(degPerSec, strength, useSlowest);
  }

  /** Maximum clockwise rotational velocity, deg/s (a positive number). */
  public void setMaxRotVelNeg(double degPerSec) {
    setMaxRotVelNeg(degPerSec, MAX_STRENGTH, true);
  }

  /** Maximum clockwise rotational velocity. */
  public void setMaxRotVelNeg(double degPerSec, double strength, boolean useSlowest) {
    maxRotVelNeg.setDesired(degPerSec, strength, useSlowest);
  }

  /** Rotational acceleration, deg/s². */
  public void setRotAccel(double degPerSec2) {
    setRotAccel(degPerSec2, MAX_STRENGTH, true);
  }

  /** Rotational acceleration. */
  public void setRotAccel(double degPerSec2, double strength, boolean useSlowest) {
    rotAccel.setDesired(degPerSec2, strength, useSlowest);
  }

  /** Rotational deceleration, deg/s². */
  public void setRotDecel(double degPerSec2) {
    setRotDecel(degPerSec2, MAX_STRENGTH, true);
  }

  /** Rotational deceleration. */
  public void setRotDecel(double degPerSec2, double strength, boolean useFastest) {
    rotDecel.setDesired(degPerSec2, strength, useFastest);
  }

  /** Clears every channel. */
  public void reset() {
    for (ArActionDesiredChannel c : all) {
      c.reset();
    }
    headingStrength = 0;
    headingSet = false;
  }

  /** Makes this desire a copy of {@code other}. */
  public void copyFrom(ArActionDesired other) {
    for (int i = 0; i < all.length; i++) {
      all[i].copyFrom(other.all[i]);
    }
    heading = other.heading;
    headingStrength = other.headingStrength;
    headingSet = other.headingSet;
  }

  // ------------------------------------------------------------------ getters

  /** Desired velocity, mm/s. */
  public double getVel() {
    return vel.getDesired();
  }

  /** Strength of the velocity. */
  public double getVelStrength() {
    return vel.getStrength();
  }

  /** The absolute heading set with {@link #setHeading}, degrees. */
  public double getHeading() {
    return heading;
  }

  /** Strength of the absolute heading. */
  public double getHeadingStrength() {
    return headingStrength;
  }

  /** Whether an absolute heading is pending conversion. */
  public boolean isHeadingSet() {
    return headingSet;
  }

  /** Desired change of heading, degrees. */
  public double getDeltaHeading() {
    return deltaHeading.getDesired();
  }

  /** Strength of the change of heading. */
  public double getDeltaHeadingStrength() {
    return deltaHeading.getStrength();
  }

  /** Desired rotational velocity, deg/s. */
  public double getRotVel() {
    return rotVel.getDesired();
  }

  /** Strength of the rotational velocity. */
  public double getRotVelStrength() {
    return rotVel.getStrength();
  }

  /** Maximum forward velocity. */
  public double getMaxVel() {
    return maxVel.getDesired();
  }

  /** Strength of the maximum forward velocity. */
  public double getMaxVelStrength() {
    return maxVel.getStrength();
  }

  /** Maximum backward velocity (negative). */
  public double getMaxNegVel() {
    return maxNegVel.getDesired();
  }

  /** Strength of the maximum backward velocity. */
  public double getMaxNegVelStrength() {
    return maxNegVel.getStrength();
  }

  /** Translational acceleration. */
  public double getTransAccel() {
    return transAccel.getDesired();
  }

  /** Strength of the translational acceleration. */
  public double getTransAccelStrength() {
    return transAccel.getStrength();
  }

  /** Translational deceleration. */
  public double getTransDecel() {
    return transDecel.getDesired();
  }

  /** Strength of the translational deceleration. */
  public double getTransDecelStrength() {
    return transDecel.getStrength();
  }

  /** Maximum rotational velocity. */
  public double getMaxRotVel() {
    return maxRotVel.getDesired();
  }

  /** Strength of the maximum rotational velocity. */
  public double getMaxRotVelStrength() {
    return maxRotVel.getStrength();
  }

  /** Maximum counter-clockwise rotational velocity. */
  public double getMaxRotVelPos() {
    return maxRotVelPos.getDesired();
  }

  /** Strength of the counter-clockwise limit. */
  public double getMaxRotVelPosStrength() {
    return maxRotVelPos.getStrength();
  }

  /** Maximum clockwise rotational velocity. */
  public double getMaxRotVelNeg() {
    return maxRotVelNeg.getDesired();
  }

  /** Strength of the clockwise limit. */
  public double getMaxRotVelNegStrength() {
    return maxRotVelNeg.getStrength();
  }

  /** Rotational acceleration. */
  public double getRotAccel() {
    return rotAccel.getDesired();
  }

  /** Strength of the rotational acceleration. */
  public double getRotAccelStrength() {
    return rotAccel.getStrength();
  }

  /** Rotational deceleration. */
  public double getRotDecel() {
    return rotDecel.getDesired();
  }

  /** Strength of the rotational deceleration. */
  public double getRotDecelStrength() {
    return rotDecel.getStrength();
  }

  // ------------------------------------------------------------------ combining

  /**
   * Turns a pending absolute heading into a change of heading from {@code robotHeading}. The
   * resolver calls this before merging.
   */
  public void accountForRobotHeading(double robotHeading) {
    if (headingSet) {
      setDeltaHeading(ArMath.subAngle(heading, robotHeading), headingStrength);
    }
    headingSet = false;
  }

  /**
   * Merges a lower-priority desire into this one: each channel only takes what strength it has
   * left. Delta heading and rotational velocity exclude each other: whichever this desire already
   * uses is the one merged.
   */
  public void merge(ArActionDesired other) {
    if (other == null) {
      return;
    }
    vel.merge(other.vel);
    if (deltaHeading.getStrength() > NO_STRENGTH) {
      deltaHeading.merge(other.deltaHeading);
    } else if (rotVel.getStrength() > NO_STRENGTH) {
      rotVel.merge(other.rotVel);
    } else {
      deltaHeading.merge(other.deltaHeading);
      rotVel.merge(other.rotVel);
    }
    for (int i = FIRST_LIMIT; i < all.length; i++) {
      all[i].merge(other.all[i]);
    }
  }

  /** Starts averaging desires of equal priority: this desire is the first of them. */
  public void startAverage() {
    for (ArActionDesiredChannel c : all) {
      c.startAverage();
    }
  }

  /** Adds a desire of equal priority to the average. */
  public void addAverage(ArActionDesired other) {
    if (other == null) {
      return;
    }
    vel.addAverage(other.vel);
    if (rotVel.getStrength() > NO_STRENGTH) {
      rotVel.addAverage(other.rotVel);
    } else if (deltaHeading.getStrength() > NO_STRENGTH) {
      deltaHeading.addAverage(other.deltaHeading);
    } else {
      rotVel.addAverage(other.rotVel);
      deltaHeading.addAverage(other.deltaHeading);
    }
    for (int i = FIRST_LIMIT; i < all.length; i++) {
      all[i].addAverage(other.all[i]);
    }
  }

  /** Finishes the average: values are strength-weighted, strengths summed (at most 1). */
  public void endAverage() {
    for (ArActionDesiredChannel c : all) {
      c.endAverage();
    }
  }

  /**
   * Corrects values no robot can use (negative maximum speeds, a positive backwards limit...),
   * logging which action asked for them. Values that were NaN or infinite were already dropped when
   * set (the channel has no strength); this logs which action set them.
   */
  public void sanityCheck(String actionName) {
    for (int i = 0; i < all.length; i++) {
      if (all[i].takeRejected()) {
        log.warn("action '{}' set {} to NaN or infinity; ignored", actionName, CHANNEL_NAMES[i]);
      }
    }
    if (headingRejected) {
      headingRejected = false;
      log.warn("action '{}' set heading to NaN or infinity; ignored", actionName);
    }
    check(actionName, "maxVel", maxVel.checkLowerBound(0));
    check(actionName, "maxNegVel", maxNegVel.checkUpperBound(0));
    check(actionName, "transAccel", transAccel.checkLowerBound(1));
    check(actionName, "transDecel", transDecel.checkLowerBound(1));
    check(actionName, "maxRotVel", maxRotVel.checkLowerBound(0));
    check(actionName, "maxRotVelPos", maxRotVelPos.checkLowerBound(0));
    check(actionName, "maxRotVelNeg", maxRotVelNeg.checkLowerBound(0));
    check(actionName, "rotAccel", rotAccel.checkLowerBound(1));
    check(actionName, "rotDecel", rotDecel.checkLowerBound(1));
  }

  private static void check(String action, String channel, boolean corrected) {
    if (corrected) {
      log.warn("action '{}' set {} out of range; corrected", action, channel);
    }
  }

  /** Whether any channel has strength. */
  public boolean isAnythingDesired() {
    if (headingSet) {
      return true;
    }
    for (ArActionDesiredChannel c : all) {
      if (c.getStrength() >= MIN_STRENGTH) {
        return true;
      }
    }
    return false;
  }

  @Override
  public String toString() {
    return "ArActionDesired[vel="
        + vel
        + ", deltaHeading="
        + deltaHeading
        + ", rotVel="
        + rotVel
        + ", maxVel="
        + maxVel
        + ", maxNegVel="
        + maxNegVel
        + ", maxRotVel="
        + maxRotVel
        + "]";
  }
}
