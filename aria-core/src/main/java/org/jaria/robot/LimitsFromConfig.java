package org.jaria.robot;

import org.jaria.params.ArRobotParams;
import org.jaria.protocol.packets.ArConfigPacket;

/**
 * Sets a newly connected robot's speed limits as ARIA does: from the CONFIGpac when one came (top
 * speeds, maxima, accelerations), overridden by the non-zero values of the robot's parameter file;
 * from the parameter file's top speeds when none came. Then asks for the IOpac and ENCODERpac
 * streams the parameters want.
 */
final class LimitsFromConfig {

  private LimitsFromConfig() {}

  /**
   * Applies the limits to {@code robot}.
   *
   * @param config the CONFIGpac received, or null if none came
   */
  static void apply(ArRobot robot, ArConfigPacket config, ArRobotParams p) {
    boolean gotConfig = config != null;
    if (gotConfig) {
      robot.setAbsoluteMaxTransVel(config.getTransVelTop());
      robot.setAbsoluteMaxRotVel(config.getRotVelTop());
      robot.setTransVelMax(config.getTransVelMax());
      robot.setRotVelMax(config.getRotVelMax());
      robot.setTransAccel(config.getInt(ArConfigPacket.Field.TRANS_ACCEL));
      robot.setTransDecel(config.getInt(ArConfigPacket.Field.TRANS_DECEL));
      robot.setRotAccel(config.getInt(ArConfigPacket.Field.ROT_ACCEL));
      robot.setRotDecel(config.getInt(ArConfigPacket.Field.ROT_DECEL));
    } else {
      robot.setAbsoluteMaxTransVel(p.getAbsoluteMaxVelocity());
      robot.setAbsoluteMaxRotVel(p.getAbsoluteMaxRotVelocity());
    }
    if (Math.abs(p.getTransVelMax()) > 1) {
      robot.setTransVelMax(p.getTransVelMax());
    } else if (!gotConfig) {
      robot.setTransVelMax(p.getAbsoluteMaxVelocity());
    }
    if (Math.abs(p.getRotVelMax()) > 1) {
      robot.setRotVelMax(p.getRotVelMax());
    } else if (!gotConfig) {
      robot.setRotVelMax(p.getAbsoluteMaxRotVelocity());
    }
    if (Math.abs(p.getTransAccel()) > 1) {
      robot.setTransAccel(p.getTransAccel());
    }
    if (Math.abs(p.getTransDecel()) > 1) {
      robot.setTransDecel(p.getTransDecel());
    }
    if (Math.abs(p.getRotAccel()) > 1) {
      robot.setRotAccel(p.getRotAccel());
    }
    if (Math.abs(p.getRotDecel()) > 1) {
      robot.setRotDecel(p.getRotDecel());
    }
    if (p.getRequestIOPackets()) {
      robot.requestIOPackets();
    }
    if (p.getRequestEncoderPackets()) {
      robot.requestEncoderPackets();
    }
  }
}
