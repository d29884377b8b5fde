package org.jaria.robot;

import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArActionDesired;
import org.jaria.geom.ArMath;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.DirectMotion.RotType;
import org.jaria.robot.DirectMotion.TransType;
import org.jaria.robot.ReflectionMemory.LastAction;
import org.jaria.robot.ReflectionMemory.LastDirect;
import org.jaria.robot.ReflectionMemory.SentAt;
import org.jaria.robot.ReflectionMemory.SentLimits;

/**
 * ARIA's state reflection for motion as a function: from what the program asked for (motion
 * commands, the actions' resolved desire), the robot's status, the time and what went out before,
 * it computes the commands this cycle sends ({@link CycleCommands}). It sends nothing itself, so a
 * test checks it with plain values.
 *
 * <p>The rules: a motion command takes precedence over actions for its axis (translation or
 * rotation), forever or for the precedence time; each value goes out when it changes, when control
 * has just passed from motion commands back to the actions, and every refresh time anyway; limits
 * (SETV, SETRV, SETA, SETRA) go out when they change; and when nothing went out for a refresh time,
 * a PULSE keeps the robot's watchdog from stopping it.
 */
final class StateReflection {

  /**
   * How state reflection is set up.
   *
   * @param doStateReflection whether motion is reflected at all (ARIA's constructor flag); without,
   *     only the PULSE goes out
   * @param refreshNanos how often unchanged values go out again
   * @param precedenceNanos how long a motion command keeps precedence; 0 for until cleared
   * @param hasMoveCommand whether the robot takes MOVE (else {@code move} drives by velocity)
   * @param vel2Divisor mm/s per VEL2 unit
   * @param limits the program's speed limits and accelerations
   */
  record Settings(
      boolean doStateReflection,
      long refreshNanos,
      long precedenceNanos,
      boolean hasMoveCommand,
      double vel2Divisor,
      MotionLimits.Values limits) {}

  /**
   * Everything one cycle's decision depends on besides the memory.
   *
   * @param now the clock time of this cycle, ns
   * @param direct the motion commands asked for
   * @param desired the actions' resolved desire (read only; no strength anywhere if no action)
   * @param status the robot's latest status (with the encoder→global transform that HEAD undoes)
   * @param settings how state reflection is set up
   */
  record Inputs(
      long now,
      DirectMotion direct,
      ArActionDesired desired,
      RobotStatus status,
      Settings settings) {}

  private StateReflection() {}

  /** The commands this cycle sends, and what to remember for the next. */
  static CycleCommands decide(Inputs in, ReflectionMemory before) {
    return new Cycle(in, before).run();
  }

  // ---------------------------------------------------------------- conversions

  /**
   * Converts a global heading into the robot's own heading frame, which is what HEAD takes: undo
   * the encoder→global rotation of {@code s} and any gyro correction of the odometry heading.
   */
  static int robotHeading(double globalHeading, RobotStatus s) {
    double encTh = ArMath.subAngle(globalHeading, s.encoderTransform().getTh());
    double rawTh =
        ArMath.addAngle(encTh, ArMath.subAngle(s.rawEncoderPose().th(), s.encoderPose().th()));
    return (int) Math.round(rawTh);
  }

  /** A velocity in VEL2 units, within a signed byte. */
  static int vel2Byte(double v, double vel2Divisor) {
    long b = Math.round(v / vel2Divisor);
    return (int) Math.max(-128, Math.min(127, b));
  }

  /** A value rounded into the range of a command's integer argument. */
  static int clampShort(double v) {
    long r = Math.round(v);
    return (int) Math.max(-32767, Math.min(32767, r));
  }

  private static boolean has(double strength) {
    return strength >= ArActionDesired.MIN_STRENGTH;
  }

  /**
   * One cycle's working copy. Mutable only inside {@link #decide}: it starts from the inputs and
   * the memory and ends as a {@link CycleCommands}.
   */
  private static final class Cycle {
    private final long now;
    private final long refresh;
    private final Settings settings;
    private final MotionLimits.Values limits;
    private final ArActionDesired d;
    private final RobotStatus s;
    private final ReflectionMemory before;
    private List<MotionCommand> out = List.of();
    private DirectMotion direct;
    private boolean trying;

    // SentAt
    private long sentTrans;
    private long sentRot;
    private long sentPulse;
    // SentLimits
    private double sentTransVelMax;
    private double sentRotVelMax;
    private double sentTransAccel;
    private double sentTransDecel;
    private double sentRotAccel;
    private double sentRotDecel;
    // LastDirect
    private int lastTransVal;
    private int lastTransVal2;
    private TransType lastTransType;
    private int lastRotVal;
    private RotType lastRotType;
    private boolean transWasDirect;
    private boolean rotWasDirect;
    // LastAction
    private int actTransVal;
    private boolean actTransSet;
    private int actRotVal;
    private boolean actRotStopped;
    private boolean actRotHeading;
    private boolean actRotSet;

    Cycle(Inputs in, ReflectionMemory m) {
      now = in.now();
      settings = in.settings();
      refresh = settings.refreshNanos();
      limits = settings.limits();
      d = in.desired();
      s = in.status();
      direct = in.direct();
      before = m;
      sentTrans = m.sentAt().trans();
      sentRot = m.sentAt().rot();
      sentPulse = m.sentAt().pulse();
      SentLimits l = m.limits();
      sentTransVelMax = l.transVelMax();
      sentRotVelMax = l.rotVelMax();
      sentTransAccel = l.transAccel();
      sentTransDecel = l.transDecel();
      sentRotAccel = l.rotAccel();
      sentRotDecel = l.rotDecel();
      LastDirect ld = m.direct();
      lastTransVal = ld.transVal();
      lastTransVal2 = ld.transVal2();
      lastTransType = ld.transType();
      lastRotVal = ld.rotVal();
      lastRotType = ld.rotType();
      transWasDirect = ld.transWasDirect();
      rotWasDirect = ld.rotWasDirect();
      LastAction la = m.action();
      actTransVal = la.transVal();
      actTransSet = la.transSet();
      actRotVal = la.rotVal();
      actRotStopped = la.rotStopped();
      actRotHeading = la.rotHeading();
      actRotSet = la.rotSet();
    }

    CycleCommands run() {
      if (settings.doStateReflection()) {
        // When control passes from motion commands back to the actions, the actions' values are
        // sent at once even if unchanged since the actions last had control (ARIA waits for the
        // next refresh, leaving the robot on the old command for up to half a second).
        if (hasPrecedence(direct.transType() != TransType.NONE, direct.transSetTime())) {
          directTrans();
          transWasDirect = true;
        } else {
          trying |= actionTrans(transWasDirect);
          transWasDirect = false;
        }
        if (hasPrecedence(direct.rotType() != RotType.NONE, direct.rotSetTime())) {
          directRot();
          rotWasDirect = true;
        } else {
          trying |= actionRot(rotWasDirect);
          rotWasDirect = false;
        }
      }
      if (now - sentRot > refresh && now - sentTrans > refresh && now - sentPulse > refresh) {
        add(MotionCommand.of(ArCommands.PULSE));
        sentPulse = now;
      }
      ReflectionMemory after = remembered();
      return new CycleCommands(out.isEmpty() ? List.of() : List.copyOf(out), direct, after, trying);
    }

    /**
     * What to remember for the next cycle; the parts that did not change are the old values
     * themselves (most cycles change little, and this runs ten times a second per robot).
     */
    private ReflectionMemory remembered() {
      SentAt at = before.sentAt();
      boolean sameAt = at.trans() == sentTrans && at.rot() == sentRot && at.pulse() == sentPulse;
      SentLimits l = before.limits();
      boolean sameLimits =
          l.transVelMax() == sentTransVelMax
              && l.rotVelMax() == sentRotVelMax
              && l.transAccel() == sentTransAccel
              && l.transDecel() == sentTransDecel
              && l.rotAccel() == sentRotAccel
              && l.rotDecel() == sentRotDecel;
      LastDirect ld = before.direct();
      boolean sameDirect =
          ld.transVal() == lastTransVal
              && ld.transVal2() == lastTransVal2
              && ld.transType() == lastTransType
              && ld.rotVal() == lastRotVal
              && ld.rotType() == lastRotType
              && ld.transWasDirect() == transWasDirect
              && ld.rotWasDirect() == rotWasDirect;
      LastAction la = before.action();
      boolean sameAction =
          la.transVal() == actTransVal
              && la.transSet() == actTransSet
              && la.rotVal() == actRotVal
              && la.rotStopped() == actRotStopped
              && la.rotHeading() == actRotHeading
              && la.rotSet() == actRotSet;
      if (sameAt && sameLimits && sameDirect && sameAction) {
        return before;
      }
      return new ReflectionMemory(
          sameAt ? at : new SentAt(sentTrans, sentRot, sentPulse),
          sameLimits
              ? l
              : new SentLimits(
                  sentTransVelMax,
                  sentRotVelMax,
                  sentTransAccel,
                  sentTransDecel,
                  sentRotAccel,
                  sentRotDecel),
          sameDirect
              ? ld
              : new LastDirect(
                  lastTransVal,
                  lastTransVal2,
                  lastTransType,
                  lastRotVal,
                  lastRotType,
                  transWasDirect,
                  rotWasDirect),
          sameAction
              ? la
              : new LastAction(
                  actTransVal, actTransSet, actRotVal, actRotStopped, actRotHeading, actRotSet));
    }

    private boolean hasPrecedence(boolean set, long setTime) {
      long p = settings.precedenceNanos();
      return set && (p == 0 || now - setTime < p);
    }

    private void send(ArCommands c, int argument) {
      add(MotionCommand.of(c, argument));
    }

    private void add(MotionCommand c) {
      if (out.isEmpty()) {
        out = new ArrayList<>(4);
      }
      out.add(c);
    }

    // -------------------------------------------------------------- limits

    /** The translational limits that changed: SETV, and SETA for acceleration and deceleration. */
    private void transLimits(double velMax, double accel, double decel) {
      if (limits.settableVelMaxes() && Math.abs(sentTransVelMax - velMax) >= 1) {
        send(ArCommands.SETV, clampShort(velMax));
        sentTransVelMax = velMax;
      }
      if (limits.settableAccsDecs()
          && Math.abs(accel) > 1
          && Math.abs(sentTransAccel - accel) >= 1) {
        send(ArCommands.SETA, clampShort(accel));
        sentTransAccel = accel;
      }
      if (limits.settableAccsDecs()
          && Math.abs(decel) > 1
          && Math.abs(sentTransDecel - decel) >= 1) {
        send(ArCommands.SETA, -clampShort(decel));
        sentTransDecel = decel;
      }
    }

    /** The rotational limits that changed: SETRV, and SETRA for acceleration and deceleration. */
    private void rotLimits(double velMax, double accel, double decel) {
      if (limits.settableVelMaxes() && Math.abs(sentRotVelMax - velMax) >= 1) {
        send(ArCommands.SETRV, clampShort(velMax));
        sentRotVelMax = velMax;
      }
      if (limits.settableAccsDecs() && Math.abs(accel) > 1 && Math.abs(sentRotAccel - accel) >= 1) {
        send(ArCommands.SETRA, clampShort(accel));
        sentRotAccel = accel;
      }
      if (limits.settableAccsDecs() && Math.abs(decel) > 1 && Math.abs(sentRotDecel - decel) >= 1) {
        send(ArCommands.SETRA, -clampShort(decel));
        sentRotDecel = decel;
      }
    }

    /**
     * An action's maximum rotational velocity (capped at the top value) goes out even when the
     * robot's own maxima are not settable, as in ARIA.
     */
    private void actionRotVelMax(double wanted) {
      double max = Math.round(Math.min(wanted, limits.absMaxRotVel()));
      if (Math.abs(sentRotVelMax - max) >= 1) {
        sentRotVelMax = max;
        send(ArCommands.SETRV, clampShort(max));
      }
    }

    // -------------------------------------------------------------- motion commands

    private void directTrans() {
      actTransSet = false; // the actions must set translation again before anything is sent
      double transVelMax = limits.transVelMax();
      transLimits(transVelMax, limits.transAccel(), limits.transDecel());
      int val = clampShort(direct.transVal());
      int val2 = 0;
      boolean refreshDue = now - sentTrans >= refresh;
      TransType type = direct.transType();
      switch (type) {
        case VEL -> {
          int max = clampShort(transVelMax);
          val = Math.max(-max, Math.min(max, val));
          if (lastTransVal != val || lastTransType != type || refreshDue) {
            send(ArCommands.VEL, val);
            sentTrans = now;
          }
          trying |= Math.abs(val) > 0;
        }
        case VEL2 -> {
          val = vel2Byte(direct.transVal(), settings.vel2Divisor());
          val2 = vel2Byte(direct.transVal2(), settings.vel2Divisor());
          if (lastTransVal != val || lastTransVal2 != val2 || lastTransType != type || refreshDue) {
            add(MotionCommand.twoBytes(ArCommands.VEL2, val, val2));
            sentTrans = now;
          }
          trying |= val != 0 || val2 != 0;
        }
        case DIST_NEW, DIST -> distance(val, refreshDue);
        case IGNORE, NONE -> {
          // nothing to send
        }
      }
      lastTransVal = val;
      lastTransVal2 = val2;
      lastTransType = direct.transType();
    }

    /** MOVE once; without a MOVE command, drive by velocity and stop at the distance. */
    private void distance(int val, boolean refreshDue) {
      if (!settings.hasMoveCommand()) {
        direct = direct.withTrans(TransType.DIST, direct.transVal());
        double gone = direct.transDistStart().findDistanceTo(s.pose());
        double toGo = Math.abs(Math.abs(direct.transVal()) - gone);
        if (gone > Math.abs(direct.transVal()) || (toGo < 10 && Math.abs(s.vel()) < 30)) {
          send(ArCommands.VEL, 0);
          direct = direct.withTrans(TransType.VEL, 0);
          sentTrans = now;
          return;
        }
        trying = true;
        double v = Math.min(Math.sqrt(toGo * 200 * 2), limits.transVelMax());
        send(ArCommands.VEL, clampShort(direct.transVal() < 0 ? -v : v));
        sentTrans = now;
      } else if (direct.transType() == TransType.DIST_NEW) {
        send(ArCommands.MOVE, val);
        sentTrans = now;
        direct = direct.withTrans(TransType.DIST, direct.transVal());
        trying = true;
      } else if (refreshDue) {
        add(MotionCommand.of(ArCommands.PULSE));
        sentPulse = now;
        sentTrans = now;
      }
    }

    private void directRot() {
      actRotSet = false; // the actions must set rotation again before anything is sent
      rotLimits(limits.rotVelMax(), limits.rotAccel(), limits.rotDecel());
      RotType type = direct.rotType();
      int val = clampShort(direct.rotVal());
      boolean refreshDue = now - sentRot >= refresh;
      if (type == RotType.HEADING) {
        val = robotHeading(direct.rotVal(), s);
        double error = Math.abs(ArMath.subAngle(direct.rotVal(), s.pose().th()));
        if (lastRotVal != val || lastRotType != type || error > 1 || refreshDue) {
          send(ArCommands.HEAD, val);
          sentRot = now;
        }
        trying |= error > 1;
      } else if (type == RotType.VEL) {
        if (lastRotVal != val || lastRotType != type || refreshDue) {
          send(ArCommands.RVEL, val);
          sentRot = now;
          trying |= val != 0;
        }
      }
      lastRotVal = val;
      lastRotType = type;
    }

    // -------------------------------------------------------------- the actions' desire

    /**
     * VEL within the desire's speed limits, with the accelerations it asks for.
     *
     * @param wasDirect whether motion commands had translation last cycle (send at once)
     * @return whether the robot is being asked to move
     */
    private boolean actionTrans(boolean wasDirect) {
      double accel =
          has(d.getTransAccelStrength()) ? Math.round(d.getTransAccel()) : limits.transAccel();
      double decel =
          has(d.getTransDecelStrength()) ? Math.round(d.getTransDecel()) : limits.transDecel();
      double transVelMax = limits.transVelMax();
      transLimits(transVelMax, accel, decel);
      double maxVel =
          has(d.getMaxVelStrength()) ? Math.min(d.getMaxVel(), transVelMax) : transVelMax;
      double maxNeg =
          has(d.getMaxNegVelStrength())
              ? Math.max(-Math.abs(d.getMaxNegVel()), -transVelMax)
              : -transVelMax;
      int val;
      if (has(d.getVelStrength())) {
        val = clampShort(d.getVel());
        actTransSet = true;
      } else {
        val = actTransVal;
      }
      boolean wants = Math.abs(val) > 0;
      val = Math.max(clampShort(maxNeg), Math.min(clampShort(maxVel), val));
      if (actTransSet && (now - sentTrans >= refresh || val != actTransVal || wasDirect)) {
        send(ArCommands.VEL, val);
        sentTrans = now;
      }
      actTransVal = val;
      return wants;
    }

    /**
     * RVEL or HEAD within the desire's rotation limits (the per-direction ones included), with the
     * accelerations it asks for.
     *
     * @param wasDirect whether motion commands had rotation last cycle (send at once)
     * @return whether the robot is being asked to turn
     */
    private boolean actionRot(boolean wasDirect) {
      double accel = has(d.getRotAccelStrength()) ? Math.round(d.getRotAccel()) : limits.rotAccel();
      double decel = has(d.getRotDecelStrength()) ? Math.round(d.getRotDecel()) : limits.rotDecel();
      double velMax = limits.rotVelMax();
      boolean actionMax = has(d.getMaxRotVelStrength());
      if (actionMax) {
        // As in ARIA, an action's maximum replaces the robot's (up to the absolute maximum).
        velMax = Math.round(Math.min(d.getMaxRotVel(), limits.absMaxRotVel()));
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
      boolean wants = false;
      if (has(d.getDeltaHeadingStrength())) {
        double delta = d.getDeltaHeading();
        turnMax = delta > 0 ? posMax : negMax;
        if (Math.round(delta) == 0 || turnMax < 1) {
          stopped = true;
          heading = false;
          val = 0;
        } else {
          val = robotHeading(s.pose().th() + delta, s);
          stopped = false;
          heading = true;
          wants = true;
        }
        actRotSet = true;
      } else if (has(d.getRotVelStrength())) {
        double v = Math.max(-negMax, Math.min(posMax, d.getRotVel()));
        val = clampShort(v);
        stopped = val == 0;
        heading = false;
        wants = val != 0;
        actRotSet = true;
      } else {
        stopped = actRotStopped;
        val = actRotVal;
        heading = actRotHeading;
      }
      // A heading turn is bounded by the robot's maximum rotational velocity, so a per-direction
      // limit on the turning side is applied by lowering that maximum for the turn.
      boolean limitedTurn = heading && turnMax < velMax;
      if (actionMax || limitedTurn) {
        actionRotVelMax(limitedTurn ? turnMax : velMax);
        rotLimits(limitedTurn ? turnMax : velMax, accel, decel);
      } else {
        rotLimits(velMax, accel, decel);
      }
      if (actRotSet
          && (now - sentRot > refresh
              || wasDirect
              || stopped != actRotStopped
              || val != actRotVal
              || heading != actRotHeading)) {
        if (stopped) {
          send(ArCommands.RVEL, 0);
        } else if (heading) {
          send(ArCommands.HEAD, val);
        } else {
          send(ArCommands.RVEL, val);
        }
        sentRot = now;
      }
      actRotVal = val;
      actRotStopped = stopped;
      actRotHeading = heading;
      return wants;
    }
  }
}
