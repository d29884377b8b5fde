package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.params.ArRobotParams;
import org.jaria.params.ParamFile;
import org.jaria.params.ParamFormatException;
import org.jaria.protocol.packets.ArConfigPacket;
import org.junit.jupiter.api.Test;

/**
 * The limits a robot starts with, as a value made from its CONFIGpac and parameter file, and what
 * the motion limits become when the state reflector takes it: no robot, no connection.
 */
class ConfiguredLimitsTest {

  private static ArConfigPacket config() {
    return new ArConfigPacket()
        .set(ArConfigPacket.Field.TRANS_VEL_TOP, 1500)
        .set(ArConfigPacket.Field.ROT_VEL_TOP, 360)
        .set(ArConfigPacket.Field.TRANS_VEL_MAX, 750)
        .set(ArConfigPacket.Field.ROT_VEL_MAX, 100)
        .set(ArConfigPacket.Field.TRANS_ACCEL, 300)
        .set(ArConfigPacket.Field.TRANS_DECEL, 310)
        .set(ArConfigPacket.Field.ROT_ACCEL, 100)
        .set(ArConfigPacket.Field.ROT_DECEL, 110);
  }

  private static ArRobotParams params(String text) throws ParamFormatException {
    return ArRobotParams.defaults().overlay(ParamFile.parse(text, "test.p"));
  }

  private static MotionLimits applied(ConfiguredLimits c) {
    MotionLimits m = new MotionLimits();
    m.apply(c);
    return m;
  }

  @Test
  void theConfigPacketSetsEveryLimitWhenTheParametersLeaveThemAtZero() {
    ConfiguredLimits c = ConfiguredLimits.of(config(), ArRobotParams.defaults());
    assertEquals(new ConfiguredLimits(1500, 360, 750, 100, 300, 310, 100, 110), c);
    MotionLimits m = applied(c);
    assertEquals(1500, m.getAbsoluteMaxTransVel());
    assertEquals(750, m.getTransVelMax());
    assertEquals(110, m.getRotDecel());
  }

  @Test
  void theParameterFileOverridesTheConfigPacket() throws ParamFormatException {
    ArRobotParams p = params("TransVelMax 600\nRotAccel 50\n");
    ConfiguredLimits c = ConfiguredLimits.of(config(), p);
    assertEquals(600, c.transVelMax());
    assertEquals(100, c.rotVelMax());
    assertEquals(50, c.rotAccel());
    assertEquals(300, c.transAccel());
  }

  @Test
  void aParameterAboveTheTopSpeedIsRefusedAndTheConfigPacketsValueStays()
      throws ParamFormatException {
    // ARIA sets the CONFIGpac's maximum, then the file's, which is refused above the top speed.
    ConfiguredLimits c = ConfiguredLimits.of(config(), params("TransVelMax 2000\n"));
    assertEquals(750, c.transVelMax());
    assertEquals(750, applied(c).getTransVelMax());
  }

  @Test
  void withoutAConfigPacketTheParametersTopSpeedsAreTheLimits() {
    ArRobotParams p = ArRobotParams.defaults();
    ConfiguredLimits c = ConfiguredLimits.of(null, p);
    assertEquals(p.getAbsoluteMaxVelocity(), c.absMaxTransVel());
    assertEquals(p.getAbsoluteMaxVelocity(), c.transVelMax());
    assertEquals(p.getAbsoluteMaxRotVelocity(), c.rotVelMax());
    assertTrue(Double.isNaN(c.transAccel()), "no CONFIGpac, no file value: unchanged");
    MotionLimits m = new MotionLimits();
    m.setTransAccel(123);
    m.apply(c);
    assertEquals(123, m.getTransAccel());
    assertEquals(p.getAbsoluteMaxVelocity(), m.getTransVelMax());
  }

  @Test
  void withoutAConfigPacketARefusedParameterLeavesTheMaximumAsItWas() throws ParamFormatException {
    // No CONFIGpac to fall back to: ARIA's one call with the file's value is refused.
    MotionLimits m = new MotionLimits();
    m.setTransVelMax(400);
    m.apply(ConfiguredLimits.of(null, params("TransVelMax 9000\n")));
    assertEquals(400, m.getTransVelMax());
  }
}
