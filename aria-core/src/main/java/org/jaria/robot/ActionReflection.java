package org.jaria.robot;

import org.jaria.action.ArActionDesired;
import org.jaria.protocol.ArCommands;

/**
 * The half of state reflection that turns the actions' resolved desire into robot commands: VEL
 * within the desire's speed limits, RVEL or HEAD within its rotation limits (including the
 * per-direction ones), and the accelerations it asks for. Values are sent when they change, when
 * control has just come back from direct motion commands, and every refresh time anyway.
 *
 * <p>Not thread-safe on its own: {@link MotionReflector} calls it under its monitor.
 */
final class ActionReflection {

  private final ArRobotPacketSender sender;
  private final MotionLimits limits;
  private final SentTimes sent;

  private int lastTransVal;
  private boolean transSet;
  private int lastRotVal;
  private boolean lastRotStopped;
  private boolean lastRotHeading;
  private boolean rotSet;

  ActionReflection(ArRobotPacketSender sender, MotionLimits limits, SentTimes sent) {
    this.sender = sender;
    this.limits = limits;
    this.sent = sent;
  }

  /** Forgets what the actions last wanted (a new connection). */
  void reset() {
    lastTransVal = 0;
    lastRotVal = 0;
    lastRotStopped = false;
    lastRotHeading = false;
  }

  /** A STOP went out: the actions' last values are now zero. */
  void stopped() {
    lastTransVal = 0;
    lastRotStopped = true;
    lastRotHeading = false;
  }

  /** Direct motion has translation: the actions must set it again before anything is sent. */
  void directTrans() {
    transSet = false;
  }

  /** Direct motion has rotation: the actions must set it again before anything is sent. */
  void directRot() {
    rotSet = false;
  }

  /**
   * Sends the translation the desire asks for.
   *
   * @param wasDirect whether direct motion had translation last cycle (send at once)
   * @return whether the robot is being asked to move
   */
  boolean reflectTrans(long now, long refreshNanos, ArActionDesired d, boolean wasDirect) {
    double accel =
        has(d.getTransAccelStrength()) ? Math.round(d.getTransAccel()) : limits.getTransAccel();
    double decel =
        has(d.getTransDecelStrength()) ? Math.round(d.getTransDecel()) : limits.getTransDecel();
    double transVelMax = limits.getTransVelMax();
    limits.sendTrans(sender, transVelMax, accel, decel);
    double maxVel = has(d.getMaxVelStrength()) ? Math.min(d.getMaxVel(), transVelMax) : transVelMax;
    double maxNeg =
        has(d.getMaxNegVelStrength())
            ? Math.max(-Math.abs(d.getMaxNegVel()), -transVelMax)
            : -transVelMax;
    int val;
    if (has(d.getVelStrength())) {
      val = MotionReflector.clampShort(d.getVel());
      transSet = true;
    } else {
      val = lastTransVal;
    }
    boolean trying = Math.abs(val) > 0;
    val =
        Math.max(
            MotionReflector.clampShort(maxNeg), Math.min(MotionReflector.clampShort(maxVel), val));
    if (transSet && (now - sent.trans >= refreshNanos || val != lastTransVal || wasDirect)) {
      sender.comInt(ArCommands.VEL.getNumber(), val);
      sent.trans = now;
    }
    lastTransVal = val;
    return trying;
  }

  /**
   * Sends the rotation the desire asks for.
   *
   * @param s the robot's state (its heading, and the frames HEAD's argument is converted into)
   * @param encoderTransformTh the encoder→global rotation, degrees
   * @param wasDirect whether direct motion had rotation last cycle (send at once)
   * @return whether the robot is being asked to turn
   */
  boolean reflectRot(
      long now,
      long refreshNanos,
      ArActionDesired d,
      RobotStatus s,
      double encoderTransformTh,
      boolean wasDirect) {
    double accel =
        has(d.getRotAccelStrength()) ? Math.round(d.getRotAccel()) : limits.getRotAccel();
    double decel =
        has(d.getRotDecelStrength()) ? Math.round(d.getRotDecel()) : limits.getRotDecel();
    double velMax = limits.getRotVelMax();
    boolean actionMax = has(d.getMaxRotVelStrength());
    if (actionMax) {
      // As in ARIA, an action's maximum replaces the robot's (up to the absolute maximum).
      velMax = limits.cappedRotVelMax(d.getMaxRotVel());
    }
    // Per-direction limits (ARIA's maxRotVelPos/Neg): positive is counter-clockwise.
    double posMax =
        has(d.getMaxRotVelPosStrength()) ? Math.min(velMax, d.getMaxRotVelPos()) : velMax;
    double negMax =
        has(d.getMaxRotVelNegStrength()) ? Math.min(velMax, d.getMaxRotVelNeg()) : velMax;

    boolean stopped;
    boolean heading;
    int val;
    double turnMax = velMax;
    boolean trying = false;
    if (has(d.getDeltaHeadingStrength())) {
      double delta = d.getDeltaHeading();
      turnMax = delta > 0 ? posMax : negMax;
      if (Math.round(delta) == 0 || turnMax < 1) {
        stopped = true;
        heading = false;
        val = 0;
      } else {
        val = MotionReflector.robotHeading(s.pose().th() + delta, s, encoderTransformTh);
        stopped = false;
        heading = true;
        trying = true;
      }
      rotSet = true;
    } else if (has(d.getRotVelStrength())) {
      double v = Math.max(-negMax, Math.min(posMax, d.getRotVel()));
      val = MotionReflector.clampShort(v);
      stopped = val == 0;
      heading = false;
      trying = val != 0;
      rotSet = true;
    } else {
      stopped = lastRotStopped;
      val = lastRotVal;
      heading = lastRotHeading;
    }
    // A heading turn is bounded by the robot's maximum rotational velocity, so a per-direction
    // limit on the turning side is applied by lowering that maximum for the turn.
    boolean limitedTurn = heading && turnMax < velMax;
    if (actionMax || limitedTurn) {
      limits.sendActionRotVelMax(sender, limitedTurn ? turnMax : velMax);
      limits.sendRot(sender, limitedTurn ? turnMax : velMax, accel, decel);
    } else {
      limits.sendRot(sender, velMax, accel, decel);
    }
    if (rotSet
        && (now - sent.rot > refreshNanos
            || wasDirect
            || stopped != lastRotStopped
            || val != lastRotVal
            || heading != lastRotHeading)) {
      if (stopped) {
        sender.comInt(ArCommands.RVEL.getNumber(), 0);
      } else if (heading) {
        sender.comInt(ArCommands.HEAD.getNumber(), val);
      } else {
        sender.comInt(ArCommands.RVEL.getNumber(), val);
      }
      sent.rot = now;
    }
    lastRotVal = val;
    lastRotStopped = stopped;
    lastRotHeading = heading;
    return trying;
  }

  private static boolean has(double strength) {
    return strength >= ArActionDesired.MIN_STRENGTH;
  }
}
