package org.jaria.robot;

import org.jaria.protocol.ArCommands;

/**
 * The robot's speed and acceleration limits as the program set them (SETV, SETRV, SETA, SETRA), the
 * top values the robot allows, and what was last sent, so each limit goes out only when it changes.
 * Thread-safe: every method holds this object's monitor.
 */
final class MotionLimits {

  private boolean settableVelMaxes = true;
  private boolean settableAccsDecs = true;
  private double absMaxTransVel = 5000;
  private double absMaxRotVel = 500;
  private double transVelMax;
  private double rotVelMax;
  private double transAccel;
  private double transDecel;
  private double rotAccel;
  private double rotDecel;
  private double sentTransVelMax;
  private double sentRotVelMax;
  private double sentTransAccel;
  private double sentTransDecel;
  private double sentRotAccel;
  private double sentRotDecel;

  synchronized void configure(boolean velMaxes, boolean accsDecs) {
    settableVelMaxes = velMaxes;
    settableAccsDecs = accsDecs;
  }

  /** Forgets what was sent (a new connection starts from the robot's own values). */
  synchronized void forgetSent() {
    sentTransVelMax = 0;
    sentRotVelMax = 0;
    sentTransAccel = 0;
    sentTransDecel = 0;
    sentRotAccel = 0;
    sentRotDecel = 0;
  }

  synchronized void setAbsoluteMaxTransVel(double v) {
    absMaxTransVel = Math.abs(v);
    if (transVelMax > absMaxTransVel) {
      transVelMax = absMaxTransVel;
    }
  }

  synchronized double getAbsoluteMaxTransVel() {
    return absMaxTransVel;
  }

  synchronized void setAbsoluteMaxRotVel(double v) {
    absMaxRotVel = Math.abs(v);
    if (rotVelMax > absMaxRotVel) {
      rotVelMax = absMaxRotVel;
    }
  }

  synchronized double getAbsoluteMaxRotVel() {
    return absMaxRotVel;
  }

  synchronized boolean setTransVelMax(double v) {
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
    transAccel = Math.abs(a);
  }

  synchronized double getTransAccel() {
    return transAccel;
  }

  synchronized void setTransDecel(double a) {
    transDecel = Math.abs(a);
  }

  synchronized double getTransDecel() {
    return transDecel;
  }

  synchronized void setRotAccel(double a) {
    rotAccel = Math.abs(a);
  }

  synchronized double getRotAccel() {
    return rotAccel;
  }

  synchronized void setRotDecel(double a) {
    rotDecel = Math.abs(a);
  }

  synchronized double getRotDecel() {
    return rotDecel;
  }

  /**
   * Sends the translational limits that changed: {@code velMax} (SETV) and the acceleration and
   * deceleration (SETA ±), each only if the robot lets them be set.
   */
  synchronized void sendTrans(
      ArRobotPacketSender sender, double velMax, double accel, double decel) {
    if (settableVelMaxes && Math.abs(sentTransVelMax - velMax) >= 1) {
      sender.comInt(ArCommands.SETV.getNumber(), MotionReflector.clampShort(velMax));
      sentTransVelMax = velMax;
    }
    if (settableAccsDecs && Math.abs(accel) > 1 && Math.abs(sentTransAccel - accel) >= 1) {
      sender.comInt(ArCommands.SETA.getNumber(), MotionReflector.clampShort(accel));
      sentTransAccel = accel;
    }
    if (settableAccsDecs && Math.abs(decel) > 1 && Math.abs(sentTransDecel - decel) >= 1) {
      sender.comInt(ArCommands.SETA.getNumber(), -MotionReflector.clampShort(decel));
      sentTransDecel = decel;
    }
  }

  /** Sends the rotational limits that changed (SETRV, SETRA ±). */
  synchronized void sendRot(ArRobotPacketSender sender, double velMax, double accel, double decel) {
    if (settableVelMaxes && Math.abs(sentRotVelMax - velMax) >= 1) {
      sender.comInt(ArCommands.SETRV.getNumber(), MotionReflector.clampShort(velMax));
      sentRotVelMax = velMax;
    }
    if (settableAccsDecs && Math.abs(accel) > 1 && Math.abs(sentRotAccel - accel) >= 1) {
      sender.comInt(ArCommands.SETRA.getNumber(), MotionReflector.clampShort(accel));
      sentRotAccel = accel;
    }
    if (settableAccsDecs && Math.abs(decel) > 1 && Math.abs(sentRotDecel - decel) >= 1) {
      sender.comInt(ArCommands.SETRA.getNumber(), -MotionReflector.clampShort(decel));
      sentRotDecel = decel;
    }
  }

  /** An action's maximum rotational velocity as used: rounded and capped at the top value. */
  synchronized double cappedRotVelMax(double wanted) {
    return Math.round(Math.min(wanted, absMaxRotVel));
  }

  /**
   * Sends an action's maximum rotational velocity (capped at the top value) even when the robot's
   * own maxima are not settable, as ARIA does; returns the value used.
   */
  synchronized double sendActionRotVelMax(ArRobotPacketSender sender, double wanted) {
    double max = Math.round(Math.min(wanted, absMaxRotVel));
    if (Math.abs(sentRotVelMax - max) >= 1) {
      sentRotVelMax = max;
      sender.comInt(ArCommands.SETRV.getNumber(), MotionReflector.clampShort(max));
    }
    return max;
  }
}
