package org.jaria.robot;

import org.jaria.geom.ArPose;

/**
 * What the program last asked for with motion commands ({@code setVel}, {@code move}, {@code
 * setHeading} ...), one axis at a time, and when. A value: the robot keeps the latest and state
 * reflection reads it once per cycle.
 *
 * @param transType what controls translation
 * @param transVal velocity (mm/s), distance (mm) or left wheel velocity, by {@code transType}
 * @param transVal2 right wheel velocity for VEL2, mm/s
 * @param transSetTime clock time of the last translation command
 * @param transDistStart where the robot was when a {@code move} was asked for
 * @param rotType what controls rotation
 * @param rotVal rotational velocity (deg/s) or global heading (degrees), by {@code rotType}
 * @param rotSetTime clock time of the last rotation command
 */
record DirectMotion(
    TransType transType,
    double transVal,
    double transVal2,
    long transSetTime,
    ArPose transDistStart,
    RotType rotType,
    double rotVal,
    long rotSetTime) {

  /** What controls translation. */
  enum TransType {
    /** Nothing direct: actions may drive. */
    NONE,
    /** A velocity (VEL). */
    VEL,
    /** A velocity per wheel (VEL2). */
    VEL2,
    /** A distance not sent yet. */
    DIST_NEW,
    /** A distance being driven. */
    DIST,
    /** Direct control that sends nothing (rotation while VEL2 drives both wheels). */
    IGNORE
  }

  /** What controls rotation. */
  enum RotType {
    /** Nothing direct: actions may turn. */
    NONE,
    /** A rotational velocity (RVEL). */
    VEL,
    /** A global heading (HEAD). */
    HEADING,
    /** Direct control that sends nothing. */
    IGNORE
  }

  /** No motion command: the actions drive. */
  static final DirectMotion NONE =
      new DirectMotion(TransType.NONE, 0, 0, 0, ArPose.ORIGIN, RotType.NONE, 0, 0);

  /** The same request with another translation. */
  DirectMotion withTrans(TransType type, double val, double val2, long setTime, ArPose start) {
    return new DirectMotion(type, val, val2, setTime, start, rotType, rotVal, rotSetTime);
  }

  /** The same request with another translation type and value (time and start kept). */
  DirectMotion withTrans(TransType type, double val) {
    return withTrans(type, val, transVal2, transSetTime, transDistStart);
  }

  /** The same request with another rotation. */
  DirectMotion withRot(RotType type, double val, long setTime) {
    return new DirectMotion(
        transType, transVal, transVal2, transSetTime, transDistStart, type, val, setTime);
  }
}
