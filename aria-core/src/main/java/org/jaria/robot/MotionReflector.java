package org.jaria.robot;

import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.jaria.action.ArActionDesired;
import org.jaria.clock.Clock;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;

/**
 * ARIA's state reflection for motion: remembers what the program asked for (by motion commands or
 * by the actions' resolved desire) and, once per cycle, sends the robot the commands that make it
 * so — again when a value changes, and every refresh time (500 ms) anyway, with a PULSE when
 * nothing else went out, so the robot's watchdog never trips.
 *
 * <p>Direct motion commands ({@link #setVel} ...) take precedence over actions: forever, or for the
 * precedence time after the last such command if one is set; {@link #clearDirectMotion} hands
 * control back to the actions. Translation and rotation are separate: a program can drive with
 * {@code setVel} while actions steer.
 *
 * <p>Setters may be called from any thread; all state is guarded by this object's monitor.
 */
final class MotionReflector {

  /** What controls translation. */
  enum TransType {
    /** Nothing direct: actions may drive. */
    NONE,
    VEL,
    VEL2,
    DIST_NEW,
    DIST,
    /** Direct control that sends nothing (e.g. a program driving with com()). */
    IGNORE
  }

  /** What controls rotation. */
  enum RotType {
    NONE,
    VEL,
    HEADING,
    IGNORE
  }

  private final Clock clock;
  private final ArRobotPacketSender sender;
  private final Supplier<RobotStatus> status;

  private boolean doStateReflection = true;
  private long refreshNanos = TimeUnit.MILLISECONDS.toNanos(500);
  private long precedenceMs;
  private boolean hasMoveCommand = true;
  private double vel2Divisor = 20;
  private final MotionLimits limits = new MotionLimits();
  private final SentTimes sent = new SentTimes();
  private final ActionReflection actions;

  private TransType transType = TransType.NONE;
  private double transVal;
  private double transVal2;
  private long transSetTime;
  private ArPose transDistStart = ArPose.ORIGIN;
  private RotType rotType = RotType.NONE;
  private double rotVal;
  private long rotSetTime;

  private int lastTransVal;
  private int lastTransVal2;
  private TransType lastTransType = TransType.NONE;
  private int lastRotVal;
  private RotType lastRotType = RotType.NONE;

  private boolean transWasDirect;
  private boolean rotWasDirect;
  private boolean tryingToMove;

  private double moveDoneDist = 40;
  private double headingDoneDiff = 3;

  MotionReflector(Clock clock, ArRobotPacketSender sender, Supplier<RobotStatus> status) {
    this.clock = clock;
    this.sender = sender;
    this.status = status;
    this.actions = new ActionReflection(sender, limits, sent);
  }

  // ---------------------------------------------------------------- configuration

  synchronized void configure(
      boolean velMaxes, boolean accsDecs, boolean moveCommand, double vel2Div) {
    limits.configure(velMaxes, accsDecs);
    hasMoveCommand = moveCommand;
    vel2Divisor = vel2Div <= 0 ? 20 : vel2Div;
  }

  synchronized void setDoStateReflection(boolean on) {
    doStateReflection = on;
  }

  synchronized void setRefreshMillis(long ms) {
    refreshNanos = TimeUnit.MILLISECONDS.toNanos(ms);
  }

  synchronized long getRefreshMillis() {
    return TimeUnit.NANOSECONDS.toMillis(refreshNanos);
  }

  synchronized void setDirectMotionPrecedenceTime(long ms) {
    precedenceMs = Math.max(0, ms);
  }

  synchronized long getDirectMotionPrecedenceTime() {
    return precedenceMs;
  }

  /** Forgets everything sent (a new connection). */
  synchronized void reset() {
    transType = TransType.NONE;
    rotType = RotType.NONE;
    lastTransType = TransType.NONE;
    lastRotType = RotType.NONE;
    limits.forgetSent();
    actions.reset();
    sent.resetTo(clock.nanoTime());
  }

  /** The speed and acceleration limits (thread-safe on their own). */
  MotionLimits limits() {
    return limits;
  }

  // ---------------------------------------------------------------- direct motion

  synchronized void setVel(double v) {
    transType = TransType.VEL;
    transVal = v;
    transSetTime = clock.nanoTime();
    if (!doStateReflection) {
      sender.comInt(ArCommands.VEL.getNumber(), clampShort(v));
    }
  }

  synchronized void setVel2(double left, double right) {
    transType = TransType.VEL2;
    transVal = left;
    transVal2 = right;
    rotType = RotType.IGNORE;
    long now = clock.nanoTime();
    transSetTime = now;
    rotSetTime = now;
    if (!doStateReflection) {
      sender.com2Bytes(ArCommands.VEL2.getNumber(), vel2Byte(left), vel2Byte(right));
    }
  }

  synchronized void move(double distance) {
    transType = TransType.DIST_NEW;
    transVal = distance;
    transSetTime = clock.nanoTime();
    transDistStart = status.get().pose();
    if (!doStateReflection) {
      sender.comInt(ArCommands.MOVE.getNumber(), clampShort(distance));
      transType = TransType.DIST;
    }
  }

  synchronized boolean isMoveDone(double delta) {
    if (Math.abs(delta) < 0.001) {
      delta = moveDoneDist;
    }
    if (transType != TransType.DIST && transType != TransType.DIST_NEW) {
      return true;
    }
    double gone = transDistStart.findDistanceTo(status.get().pose());
    return Math.abs(gone - Math.abs(transVal)) < delta;
  }

  synchronized void setMoveDoneDist(double d) {
    moveDoneDist = d;
  }

  synchronized double getMoveDoneDist() {
    return moveDoneDist;
  }

  synchronized void setRotVel(double v) {
    rotType = RotType.VEL;
    rotVal = v;
    rotSetTime = clock.nanoTime();
    if (!doStateReflection) {
      sender.comInt(ArCommands.RVEL.getNumber(), clampShort(v));
    }
  }

  synchronized void setHeading(double heading) {
    rotType = RotType.HEADING;
    rotVal = ArMath.fixAngle(heading);
    rotSetTime = clock.nanoTime();
    if (!doStateReflection) {
      sender.comInt(ArCommands.HEAD.getNumber(), robotHeading(rotVal, status.get()));
    }
  }

  synchronized void setDeltaHeading(double delta) {
    setHeading(status.get().pose().th() + delta);
  }

  synchronized boolean isHeadingDone(double delta) {
    if (Math.abs(delta) < 0.001) {
      delta = headingDoneDiff;
    }
    if (rotType != RotType.HEADING) {
      return true;
    }
    return Math.abs(ArMath.subAngle(status.get().pose().th(), rotVal)) < delta;
  }

  synchronized void setHeadingDoneDiff(double d) {
    headingDoneDiff = d;
  }

  synchronized double getHeadingDoneDiff() {
    return headingDoneDiff;
  }

  /** Stops both axes at once and remembers that zero is what is wanted. */
  synchronized void stop() {
    sender.com(ArCommands.STOP.getNumber());
    long now = clock.nanoTime();
    transType = TransType.VEL;
    transVal = 0;
    transSetTime = now;
    rotType = RotType.VEL;
    rotVal = 0;
    rotSetTime = now;
    lastTransVal = 0;
    lastTransType = TransType.VEL;
    lastRotVal = 0;
    lastRotType = RotType.VEL;
    sent.trans = now;
    sent.rot = now;
    actions.stopped();
  }

  synchronized void clearDirectMotion() {
    transType = TransType.NONE;
    rotType = RotType.NONE;
    lastTransType = TransType.NONE;
    lastRotType = RotType.NONE;
  }

  /** Declares that translation and rotation are being driven some other way: send nothing. */
  synchronized void setIgnore() {
    long now = clock.nanoTime();
    transType = TransType.IGNORE;
    rotType = RotType.IGNORE;
    transSetTime = now;
    rotSetTime = now;
  }

  synchronized boolean isDirectMotion() {
    long now = clock.nanoTime();
    return hasPrecedence(transType != TransType.NONE, transSetTime, now)
        || hasPrecedence(rotType != RotType.NONE, rotSetTime, now);
  }

  synchronized boolean isTryingToMove() {
    return tryingToMove;
  }

  synchronized TransType transType() {
    return transType;
  }

  synchronized RotType rotType() {
    return rotType;
  }

  synchronized double transVal() {
    return transVal;
  }

  synchronized double rotVal() {
    return rotVal;
  }

  private boolean hasPrecedence(boolean set, long setTime, long now) {
    return set
        && (precedenceMs == 0 || now - setTime < TimeUnit.MILLISECONDS.toNanos(precedenceMs));
  }

  // ---------------------------------------------------------------- the cycle's reflection

  /**
   * Sends what is needed this cycle. {@code desired} is the actions' resolved desire (no strength
   * anywhere if there are no actions).
   */
  synchronized void reflect(ArActionDesired desired, double encoderTransformTh) {
    long now = clock.nanoTime();
    RobotStatus s = status.get();
    if (doStateReflection) {
      tryingToMove = false;
      // When control passes from motion commands back to the actions, the actions' values are
      // sent at once even if unchanged since the actions last had control (ARIA waits for the
      // next refresh, leaving the robot on the old command for up to half a second).
      if (hasPrecedence(transType != TransType.NONE, transSetTime, now)) {
        reflectDirectTrans(now, s);
        transWasDirect = true;
      } else {
        tryingToMove |= actions.reflectTrans(now, refreshNanos, desired, transWasDirect);
        transWasDirect = false;
      }
      if (hasPrecedence(rotType != RotType.NONE, rotSetTime, now)) {
        reflectDirectRot(now, s, encoderTransformTh);
        rotWasDirect = true;
      } else {
        tryingToMove |=
            actions.reflectRot(now, refreshNanos, desired, s, encoderTransformTh, rotWasDirect);
        rotWasDirect = false;
      }
    }
    if (now - sent.rot > refreshNanos
        && now - sent.trans > refreshNanos
        && now - sent.pulse > refreshNanos) {
      sender.com(ArCommands.PULSE.getNumber());
      sent.pulse = now;
    }
  }

  private void reflectDirectTrans(long now, RobotStatus s) {
    actions.directTrans();
    double transVelMax = limits.getTransVelMax();
    limits.sendTrans(sender, transVelMax, limits.getTransAccel(), limits.getTransDecel());
    int val = clampShort(transVal);
    int val2 = 0;
    boolean refresh = now - sent.trans >= refreshNanos;
    switch (transType) {
      case VEL -> {
        int max = clampShort(transVelMax);
        val = Math.max(-max, Math.min(max, val));
        if (lastTransVal != val || lastTransType != transType || refresh) {
          sender.comInt(ArCommands.VEL.getNumber(), val);
          sent.trans = now;
        }
        tryingToMove |= Math.abs(val) > 0;
      }
      case VEL2 -> {
        val = vel2Byte(transVal);
        val2 = vel2Byte(transVal2);
        if (lastTransVal != val || lastTransVal2 != val2 || lastTransType != transType || refresh) {
          sender.com2Bytes(ArCommands.VEL2.getNumber(), val, val2);
          sent.trans = now;
        }
        tryingToMove |= val != 0 || val2 != 0;
      }
      case DIST_NEW, DIST -> reflectDistance(now, s, val, refresh);
      case IGNORE, NONE -> {
        // nothing to send
      }
    }
    lastTransVal = val;
    lastTransVal2 = val2;
    lastTransType = transType;
  }

  /** MOVE once; without a MOVE command, drive by velocity and stop at the distance. */
  private void reflectDistance(long now, RobotStatus s, int val, boolean refresh) {
    if (!hasMoveCommand) {
      transType = TransType.DIST;
      double gone = transDistStart.findDistanceTo(s.pose());
      double toGo = Math.abs(Math.abs(transVal) - gone);
      if (gone > Math.abs(transVal) || (toGo < 10 && Math.abs(s.vel()) < 30)) {
        sender.comInt(ArCommands.VEL.getNumber(), 0);
        transType = TransType.VEL;
        transVal = 0;
        sent.trans = now;
        return;
      }
      tryingToMove = true;
      double v = Math.min(Math.sqrt(toGo * 200 * 2), limits.getTransVelMax());
      sender.comInt(ArCommands.VEL.getNumber(), clampShort(transVal < 0 ? -v : v));
      sent.trans = now;
    } else if (transType == TransType.DIST_NEW) {
      sender.comInt(ArCommands.MOVE.getNumber(), val);
      sent.trans = now;
      transType = TransType.DIST;
      tryingToMove = true;
    } else if (refresh) {
      sender.com(ArCommands.PULSE.getNumber());
      sent.pulse = now;
      sent.trans = now;
    }
  }

  private void reflectDirectRot(long now, RobotStatus s, double encoderTransformTh) {
    actions.directRot();
    limits.sendRot(sender, limits.getRotVelMax(), limits.getRotAccel(), limits.getRotDecel());
    int val = clampShort(rotVal);
    boolean refresh = now - sent.rot >= refreshNanos;
    if (rotType == RotType.HEADING) {
      val = robotHeading(rotVal, s, encoderTransformTh);
      double error = Math.abs(ArMath.subAngle(rotVal, s.pose().th()));
      if (lastRotVal != val || lastRotType != rotType || error > 1 || refresh) {
        sender.comInt(ArCommands.HEAD.getNumber(), val);
        sent.rot = now;
      }
      tryingToMove |= error > 1;
    } else if (rotType == RotType.VEL) {
      if (lastRotVal != val || lastRotType != rotType || refresh) {
        sender.comInt(ArCommands.RVEL.getNumber(), val);
        sent.rot = now;
        tryingToMove |= val != 0;
      }
    }
    lastRotVal = val;
    lastRotType = rotType;
  }

  /**
   * Converts a global heading into the robot's own heading frame, which is what HEAD takes: undo
   * the encoder→global rotation and any gyro correction of the odometry heading.
   */
  static int robotHeading(double globalHeading, RobotStatus s, double encoderTransformTh) {
    double encTh = ArMath.subAngle(globalHeading, encoderTransformTh);
    double rawTh =
        ArMath.addAngle(encTh, ArMath.subAngle(s.rawEncoderPose().th(), s.encoderPose().th()));
    return (int) Math.round(rawTh);
  }

  private int robotHeading(double globalHeading, RobotStatus s) {
    return robotHeading(globalHeading, s, ArMath.subAngle(s.pose().th(), s.encoderPose().th()));
  }

  private int vel2Byte(double v) {
    long b = Math.round(v / vel2Divisor);
    return (int) Math.max(-128, Math.min(127, b));
  }

  static int clampShort(double v) {
    long r = Math.round(v);
    return (int) Math.max(-32767, Math.min(32767, r));
  }
}
