package org.jaria.sim.server;

import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.ArConfigPacket.Field;
import org.jaria.sim.robot.MotionController;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.RobotModel;

/**
 * CONFIGpac as MobileSim fills it, for the {@code mobilesim} profile. MobileSim reports the same
 * values for every model but the type, subtype and whether it has sonar: "tops" of 9999 (it has no
 * firmware limits), a PWM maximum of 400, firmware "S.0", no bumpers, gyro, sonar cycle, battery
 * thresholds, encoder constants or gyro calibration (all 0), autobaud 2, and the session's current
 * speeds and accelerations (3000 mm/s, 150 °/s, 300 mm/s², 100 °/s² until the client changes them),
 * lateral tops of 9999 and lateral settings of 0. Both sonar rings are reported whenever the model
 * has sonar at all, as MobileSim does.
 */
final class MobileSimConfig {

  /** MobileSim's firmware version string. */
  static final String FIRMWARE = "S.0";

  /** MobileSim's stand-in for limits it does not have ("tops"). */
  static final int FAKE_TOP = 9999;

  /** MobileSim's PWM maximum. */
  static final int PWM_MAX = 400;

  /** MobileSim's autobaud byte (ARIA reads 2 as "reset baud"). */
  static final int RESET_BAUD = 2;

  private MobileSimConfig() {}

  /** CONFIGpac of {@code b} as MobileSim sends it. */
  static ArRobotPacket config(ArRobotPacket p, RobotBody b, int sipCycleMs, int watchdogMs) {
    RobotModel m = b.model();
    MotionController mc = b.motion();
    boolean sonar = m.getNumSonar() > 0;
    ArConfigPacket c = new ArConfigPacket();
    c.set(Field.TYPE, m.getRobotClass());
    c.set(Field.SUBTYPE, m.getSubtype());
    c.set(Field.SERIAL_NUMBER, ServerPackets.SERIAL);
    c.set(Field.ROT_VEL_TOP, FAKE_TOP);
    c.set(Field.TRANS_VEL_TOP, FAKE_TOP);
    c.set(Field.ROT_ACCEL_TOP, FAKE_TOP);
    c.set(Field.TRANS_ACCEL_TOP, FAKE_TOP);
    c.set(Field.PWM_MAX, PWM_MAX);
    c.set(Field.NAME, ServerPackets.ROBOT_NAME);
    c.set(Field.SIP_CYCLE_TIME, Math.min(255, sipCycleMs));
    c.set(Field.HAS_GRIPPER, b.gripper() != null ? 1 : 0);
    c.set(Field.FRONT_SONAR, sonar ? 1 : 0);
    c.set(Field.REAR_SONAR, sonar ? 1 : 0);
    c.set(Field.WATCHDOG, Math.min(65535, watchdogMs));
    c.set(Field.ROT_VEL_MAX, round(mc.getRotVelMax()));
    c.set(Field.TRANS_VEL_MAX, round(mc.getTransVelMax()));
    c.set(Field.ROT_ACCEL, round(mc.getRotAccel()));
    c.set(Field.ROT_DECEL, round(mc.getRotDecel()));
    c.set(Field.TRANS_ACCEL, round(mc.getTransAccel()));
    c.set(Field.TRANS_DECEL, round(mc.getTransDecel()));
    c.set(Field.RESET_BAUD, RESET_BAUD);
    c.set(Field.HAS_GYRO, b.gyro() != null ? 1 : 0);
    c.set(Field.FIRMWARE_VERSION, FIRMWARE);
    c.set(Field.LAT_VEL_TOP, FAKE_TOP);
    c.set(Field.LAT_ACCEL_TOP, FAKE_TOP);
    // lateral maximum, acceleration and deceleration stay 0, as MobileSim sends them
    return c.encode(p);
  }

  private static int round(double v) {
    return (int) Math.max(0, Math.min(65535, Math.round(v)));
  }
}
