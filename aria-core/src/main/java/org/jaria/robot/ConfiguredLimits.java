package org.jaria.robot;

import org.jaria.params.ArRobotParams;
import org.jaria.protocol.packets.ArConfigPacket;

/**
 * The speed limits a newly connected robot starts with, as ARIA sets them: from the CONFIGpac when
 * one came (top speeds, maxima, accelerations), overridden by the non-zero values of the robot's
 * parameter file; from the parameter file's top speeds when none came. A value: the link makes it
 * when the handshake has its CONFIGpac (or gave up waiting), and the state reflector takes it
 * ({@link MotionLimits#apply}), so configuration never goes back up through the robot's setters.
 *
 * <p>A NaN component leaves that limit as it was. The maxima obey {@link MotionLimits}'s rule: a
 * value above the top speed is refused and the limit keeps its value.
 *
 * @param absMaxTransVel the top translational velocity the robot allows, mm/s
 * @param absMaxRotVel the top rotational velocity the robot allows, deg/s
 * @param transVelMax maximum translational velocity, mm/s
 * @param rotVelMax maximum rotational velocity, deg/s
 * @param transAccel translational acceleration, mm/s², or NaN
 * @param transDecel translational deceleration, mm/s², or NaN
 * @param rotAccel rotational acceleration, deg/s², or NaN
 * @param rotDecel rotational deceleration, deg/s², or NaN
 */
record ConfiguredLimits(
    double absMaxTransVel,
    double absMaxRotVel,
    double transVelMax,
    double rotVelMax,
    double transAccel,
    double transDecel,
    double rotAccel,
    double rotDecel) {

  /**
   * The limits for a robot that sent {@code config} (null if no CONFIGpac came) and runs on
   * parameters {@code p}.
   */
  static ConfiguredLimits of(ArConfigPacket config, ArRobotParams p) {
    boolean got = config != null;
    double absTrans = got ? config.getTransVelTop() : p.getAbsoluteMaxVelocity();
    double absRot = got ? config.getRotVelTop() : p.getAbsoluteMaxRotVelocity();
    return new ConfiguredLimits(
        absTrans,
        absRot,
        velMax(p.getTransVelMax(), got, got ? config.getTransVelMax() : absTrans, absTrans),
        velMax(p.getRotVelMax(), got, got ? config.getRotVelMax() : absRot, absRot),
        accel(p.getTransAccel(), got, config, ArConfigPacket.Field.TRANS_ACCEL),
        accel(p.getTransDecel(), got, config, ArConfigPacket.Field.TRANS_DECEL),
        accel(p.getRotAccel(), got, config, ArConfigPacket.Field.ROT_ACCEL),
        accel(p.getRotDecel(), got, config, ArConfigPacket.Field.ROT_DECEL));
  }

  /**
   * A maximum: the parameter file's when it sets one (|value| > 1), else the fallback (the
   * CONFIGpac's, or the top speed when none came). ARIA sets the CONFIGpac's value first and then
   * the file's, so when the file's value is refused (not positive, or above the top speed) the
   * CONFIGpac's stays; without a CONFIGpac there is nothing to fall back to.
   */
  private static double velMax(double fromParams, boolean gotConfig, double fallback, double top) {
    boolean accepted = fromParams > 0 && fromParams <= Math.abs(top);
    if (Math.abs(fromParams) > 1 && (accepted || !gotConfig)) {
      return fromParams;
    }
    return fallback;
  }

  /** An acceleration: the parameter file's when set, else the CONFIGpac's, else unchanged. */
  private static double accel(
      double fromParams, boolean gotConfig, ArConfigPacket config, ArConfigPacket.Field field) {
    if (Math.abs(fromParams) > 1) {
      return fromParams;
    }
    return gotConfig ? config.getInt(field) : Double.NaN;
  }
}
