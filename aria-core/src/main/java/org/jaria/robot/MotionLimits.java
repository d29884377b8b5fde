package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;

/**
 * The robot's speed and acceleration limits as the program set them (ARIA's {@code setTransVelMax}
 * ...), the top values the robot allows, and whether the robot lets them be set at all. Only the
 * settings: what was last sent is state reflection's memory ({@link ReflectionMemory}). Setters may
 * be called from any thread; state reflection reads one consistent {@link #values()} per cycle.
 */
final class MotionLimits {

  /**
   * The limits at one moment.
   *
   * @param settableVelMaxes whether the robot takes SETV and SETRV
   * @param settableAccsDecs whether the robot takes SETA and SETRA
   * @param absMaxRotVel the top rotational velocity the robot allows, deg/s
   * @param transVelMax maximum translational velocity, mm/s
   * @param rotVelMax maximum rotational velocity, deg/s
   * @param transAccel translational acceleration, mm/s²
   * @param transDecel translational deceleration, mm/s²
   * @param rotAccel rotational acceleration, deg/s²
   * @param rotDecel rotational deceleration, deg/s²
   */
  record Values(
      boolean settableVelMaxes,
      boolean settableAccsDecs,
      double absMaxRotVel,
      double transVelMax,
      double rotVelMax,
      double transAccel,
      double transDecel,
      double rotAccel,
      double rotDecel) {}

  @GuardedBy("this")
  private boolean settableVelMaxes = true;

  @GuardedBy("this")
  private boolean settableAccsDecs = true;

  @GuardedBy("this")
  private double absMaxTransVel = 5000;

  @GuardedBy("this")
  private double absMaxRotVel = 500;

  @GuardedBy("this")
  private double transVelMax;

  @GuardedBy("this")
  private double rotVelMax;

  @GuardedBy("this")
  private double transAccel;

  @GuardedBy("this")
  private double transDecel;

  @GuardedBy("this")
  private double rotAccel;

  @GuardedBy("this")
  private double rotDecel;

  /** The limits as one value, made again after a change (they change rarely; cycles read often). */
  @GuardedBy("this")
  private Values values;

  synchronized void configure(boolean velMaxes, boolean accsDecs) {
    values = null;
    settableVelMaxes = velMaxes;
    settableAccsDecs = accsDecs;
  }

  /**
   * Sets the limits a newly connected robot starts with, all at once, so that a cycle sees either
   * none or all of them: the top speeds first, then the maxima (refused above the top speeds, as by
   * their setters), then the accelerations; NaN components are left as they are.
   */
  synchronized void apply(ConfiguredLimits c) {
    setAbsoluteMaxTransVel(c.absMaxTransVel());
    setAbsoluteMaxRotVel(c.absMaxRotVel());
    if (!Double.isNaN(c.transVelMax())) {
      setTransVelMax(c.transVelMax());
    }
    if (!Double.isNaN(c.rotVelMax())) {
      setRotVelMax(c.rotVelMax());
    }
    if (!Double.isNaN(c.transAccel())) {
      setTransAccel(c.transAccel());
    }
    if (!Double.isNaN(c.transDecel())) {
      setTransDecel(c.transDecel());
    }
    if (!Double.isNaN(c.rotAccel())) {
      setRotAccel(c.rotAccel());
    }
    if (!Double.isNaN(c.rotDecel())) {
      setRotDecel(c.rotDecel());
    }
  }

  /** The limits now, as one value. */
  synchronized Values values() {
    if (values != null) {
      return values;
    }
    values =
        new Values(
            settableVelMaxes,
            settableAccsDecs,
            absMaxRotVel,
            transVelMax,
            rotVelMax,
            transAccel,
            transDecel,
            rotAccel,
            rotDecel);
    return values;
  }

  synchronized void setAbsoluteMaxTransVel(double v) {
    values = null;
    absMaxTransVel = Math.abs(v);
    if (transVelMax > absMaxTransVel) {
      transVelMax = absMaxTransVel;
    }
  }

  synchronized double getAbsoluteMaxTransVel() {
    return absMaxTransVel;
  }

  synchronized void setAbsoluteMaxRotVel(double v) {
    values = null;
    absMaxRotVel = Math.abs(v);
    if (rotVelMax > absMaxRotVel) {
      rotVelMax = absMaxRotVel;
    }
  }

  synchronized double getAbsoluteMaxRotVel() {
    return absMaxRotVel;
  }

  synchronized boolean setTransVelMax(double v) {
    values = null;
    if (v <= 0 || v > absMaxTransVel) {
      return false;
    }
    transVelMax = v;
    return true;
  }

  synchronized double getTransVelMax() {
    return transVelMax;
  }

  synchronized boolean setRotVelMax(double v) {
    values = null;
    if (v <= 0 || v > absMaxRotVel) {
      return false;
    }
    rotVelMax = v;
    return true;
  }

  synchronized double getRotVelMax() {
    return rotVelMax;
  }

  synchronized void setTransAccel(double a) {
    values = null;
    transAccel = Math.abs(a);
  }

  synchronized double getTransAccel() {
    return transAccel;
  }

  synchronized void setTransDecel(double a) {
    values = null;
    transDecel = Math.abs(a);
  }

  synchronized double getTransDecel() {
    return transDecel;
  }

  synchronized void setRotAccel(double a) {
    values = null;
    rotAccel = Math.abs(a);
  }

  synchronized double getRotAccel() {
    return rotAccel;
  }

  synchronized void setRotDecel(double a) {
    values = null;
    rotDecel = Math.abs(a);
  }

  synchronized double getRotDecel() {
    return rotDecel;
  }
}
