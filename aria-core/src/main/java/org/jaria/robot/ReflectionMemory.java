package org.jaria.robot;

import org.jaria.robot.DirectMotion.RotType;
import org.jaria.robot.DirectMotion.TransType;

/**
 * What state reflection remembers from one cycle to the next: when a translation, a rotation and a
 * PULSE last went out (the refresh time and the idle PULSE depend on whatever went out last,
 * whoever asked for it), the limits last sent, and the last values of each half (motion commands,
 * actions), so that a value goes out again only when it changes. A value: each cycle makes a new
 * one.
 *
 * @param sentAt when each kind of command last went out
 * @param limits the speed limits and accelerations last sent
 * @param direct what the motion-command half last sent
 * @param action what the action half last sent
 */
record ReflectionMemory(SentAt sentAt, SentLimits limits, LastDirect direct, LastAction action) {

  /**
   * Clock times a translation, a rotation and a PULSE last went out, ns.
   *
   * @param trans last translation command (VEL, VEL2, MOVE)
   * @param rot last rotation command (RVEL, HEAD)
   * @param pulse last PULSE
   */
  record SentAt(long trans, long rot, long pulse) {}

  /**
   * The limits last sent (SETV, SETRV, SETA ±, SETRA ±); 0 for "not sent yet".
   *
   * @param transVelMax SETV
   * @param rotVelMax SETRV
   * @param transAccel SETA
   * @param transDecel SETA with a negative argument
   * @param rotAccel SETRA
   * @param rotDecel SETRA with a negative argument
   */
  record SentLimits(
      double transVelMax,
      double rotVelMax,
      double transAccel,
      double transDecel,
      double rotAccel,
      double rotDecel) {
    static final SentLimits NONE = new SentLimits(0, 0, 0, 0, 0, 0);
  }

  /**
   * What the motion-command half last sent.
   *
   * @param transVal last translation argument
   * @param transVal2 last right-wheel argument (VEL2)
   * @param transType the kind of translation command it was
   * @param rotVal last rotation argument
   * @param rotType the kind of rotation command it was
   * @param transWasDirect whether motion commands had translation last cycle
   * @param rotWasDirect whether motion commands had rotation last cycle
   */
  record LastDirect(
      int transVal,
      int transVal2,
      TransType transType,
      int rotVal,
      RotType rotType,
      boolean transWasDirect,
      boolean rotWasDirect) {}

  /**
   * What the action half last sent.
   *
   * @param transVal last VEL argument
   * @param transSet whether an action has set translation since motion commands last had it
   * @param rotVal last RVEL or HEAD argument
   * @param rotStopped whether the last rotation was a stop
   * @param rotHeading whether the last rotation was a HEAD
   * @param rotSet whether an action has set rotation since motion commands last had it
   */
  record LastAction(
      int transVal,
      boolean transSet,
      int rotVal,
      boolean rotStopped,
      boolean rotHeading,
      boolean rotSet) {}

  /** Nothing sent yet. */
  static final ReflectionMemory EMPTY =
      new ReflectionMemory(
          new SentAt(0, 0, 0),
          SentLimits.NONE,
          new LastDirect(0, 0, TransType.NONE, 0, RotType.NONE, false, false),
          new LastAction(0, false, 0, false, false, false));

  /**
   * A new connection at {@code now}: the robot starts from its own limits and values; the refresh
   * and PULSE times count from now.
   */
  ReflectionMemory connected(long now) {
    LastDirect d = direct;
    LastAction a = action;
    return new ReflectionMemory(
        new SentAt(now, now, now),
        SentLimits.NONE,
        new LastDirect(
            d.transVal(),
            d.transVal2(),
            TransType.NONE,
            d.rotVal(),
            RotType.NONE,
            d.transWasDirect(),
            d.rotWasDirect()),
        new LastAction(0, a.transSet(), 0, false, false, a.rotSet()));
  }

  /** A STOP went out at {@code now}: both halves last sent zero speed. */
  ReflectionMemory stopped(long now) {
    LastDirect d = direct;
    LastAction a = action;
    return new ReflectionMemory(
        new SentAt(now, now, sentAt.pulse()),
        limits,
        new LastDirect(
            0, d.transVal2(), TransType.VEL, 0, RotType.VEL, d.transWasDirect(), d.rotWasDirect()),
        new LastAction(0, a.transSet(), a.rotVal(), true, false, a.rotSet()));
  }

  /** Motion commands were cleared: the next ones count as new even with the same values. */
  ReflectionMemory directCleared() {
    LastDirect d = direct;
    return new ReflectionMemory(
        sentAt,
        limits,
        new LastDirect(
            d.transVal(),
            d.transVal2(),
            TransType.NONE,
            d.rotVal(),
            RotType.NONE,
            d.transWasDirect(),
            d.rotWasDirect()),
        action);
  }
}
