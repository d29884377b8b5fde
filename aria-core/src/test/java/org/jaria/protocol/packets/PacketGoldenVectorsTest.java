package org.jaria.protocol.packets;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.Hex;
import org.junit.jupiter.api.Test;

/**
 * Server packets against frames written out by hand from the field order in the protocol spec
 * ({@code shared/spec/arcos-protocol.md}), so that the codecs are checked against the wire format
 * and not only against themselves. Each frame's checksum was worked out by hand with the spec's
 * algorithm (the same routine reproduces the spec's own SYNC0, ENABLE and VEL vectors).
 *
 * <p>Every vector is decoded and its fields compared with the values it was written from, and the
 * same values are encoded and compared byte for byte with the vector.
 */
class PacketGoldenVectorsTest {

  private static ArRobotPacket load(String hex) {
    byte[] b = Hex.parse(hex);
    ArRobotPacket p = new ArRobotPacket().load(b, 0, b.length);
    assertTrue(p.verifyCheckSum(), "the hand-computed checksum is right");
    return p;
  }

  private static void assertBytes(String expectedHex, ArRobotPacket encoded) {
    assertEquals(Hex.format(Hex.parse(expectedHex)), Hex.format(encoded.toByteArray()));
  }

  // The standard SIP both with no tail and with every optional tail field.
  private static final String SIP_HEAD =
      """
      FA FB
      """;
  private static final String SIP_FIELDS =
      """
      E8 03        # XPOS 1000
      D0 07        # YPOS 2000
      00 FE        # THPOS -512
      2C 01        # L VEL 300
      6A FF        # R VEL -150
      7D           # BATTERY 12.5 V
      02 01        # STALL/BUMPERS: bumper bit 1, right motor stalled (bit 8)
      5A 00        # CONTROL 90
      03 00        # FLAGS: motors on, sonar array 1
      2D           # COMPASS 45 (90 degrees)
      02           # SONAR COUNT
      00 F4 01     # sonar 0: 500
      07 88 13     # sonar 7: 5000 (no echo)
      """;
  private static final String SIP_TAIL =
      """
      05           # GRIP_STATE
      02           # ANPORT
      C8           # ANALOG 200
      AA           # DIGIN
      55           # DIGOUT
      83 00        # BATTERYX10 131
      FF           # CHARGESTATE -1 (unknown)
      85 FF        # ROTVEL -123 (-12.3 deg/s)
      07 00        # FAULTFLAGS
      FB FF        # LATVEL -5
      1F           # TEMPERATURE 31
      58           # SOC 88
      15 CD 5B 07  # uC time 123456789
      EF BE AD DE  # FLAGS3 0xDEADBEEF
      """;

  private static StandardSip sipValues() {
    return new StandardSip()
        .setMoving(true)
        .setPos(1000, 2000, -512)
        .setWheelVels(300, -150)
        .setBattery(125)
        .setStallAndBumpers(0x0102)
        .setControl(90)
        .setFlags(0x0003)
        .setCompass(45)
        .addSonar(0, 500)
        .addSonar(7, 5000);
  }

  private static void assertMandatorySipFields(StandardSip s) {
    assertEquals(PacketIds.SIP_MOVING, s.getId());
    assertEquals(1000, s.getXPos());
    assertEquals(2000, s.getYPos());
    assertEquals(-512, s.getThPos());
    assertEquals(300, s.getLeftVel());
    assertEquals(-150, s.getRightVel());
    assertEquals(125, s.getBattery());
    assertEquals(0x0102, s.getStallAndBumpers());
    assertEquals(90, s.getControl());
    assertEquals(3, s.getFlags());
    assertEquals(45, s.getCompass());
    assertEquals(2, s.getSonarCount());
    assertEquals(0, s.getSonarNumber(0));
    assertEquals(500, s.getSonarRange(0));
    assertEquals(7, s.getSonarNumber(1));
    assertEquals(5000, s.getSonarRange(1));
  }

  @Test
  void standardSipWithoutTail() {
    String frame = SIP_HEAD + "1C 33\n" + SIP_FIELDS + "53 DC";
    StandardSip d = new StandardSip();
    assertTrue(d.decode(load(frame)));
    assertMandatorySipFields(d);
    assertEquals(0, d.getOptionalCount());
    assertBytes(frame, sipValues().setOptionalCount(0).encode(new ArRobotPacket()));
  }

  @Test
  void standardSipWithTheWholeOptionalTail() {
    String frame = SIP_HEAD + "34 33\n" + SIP_FIELDS + SIP_TAIL + "2E D0";
    StandardSip d = new StandardSip();
    assertTrue(d.decode(load(frame)));
    assertMandatorySipFields(d);
    assertEquals(StandardSip.Optional.values().length, d.getOptionalCount());
    assertEquals(5, d.getGripState());
    assertEquals(2, d.getAnPort());
    assertEquals(200, d.getAnalog());
    assertEquals(0xAA, d.getDigIn());
    assertEquals(0x55, d.getDigOut());
    assertEquals(131, d.getBatteryX10());
    assertEquals(-1, d.getChargeState());
    assertEquals(-123, d.getRotVel());
    assertEquals(7, d.getFaultFlags());
    assertEquals(-5, d.getLatVel());
    assertEquals(31, d.getTemperature());
    assertEquals(88, d.getSoc());
    assertEquals(123456789L, d.getUcTime());
    assertEquals(0xDEADBEEFL, d.getFlags3());
    StandardSip e =
        sipValues()
            .setIo(5, 2, 200, 0xAA, 0x55)
            .setPower(131, -1, -123, 7)
            .setExtended(-5, 31, 88, 123456789L, 0xDEADBEEFL)
            .setOptionalCount(StandardSip.Optional.values().length);
    assertBytes(frame, e.encode(new ArRobotPacket()));
  }

  @Test
  void ioPac() {
    String frame =
        """
        FA FB 0F F0
        04 01 00 00 FB   # 4 digin bytes: DIGIN 1, front bumps 0, rear bumps 0, IRs 0xFB
        01 0F            # 1 digout byte
        02 00 02 FF 03   # 2 analogs: 512, 1023
        F8 0E
        """;
    IoPacket d = IoPacket.decode(load(frame));
    assertNotNull(d);
    assertArrayEquals(new int[] {1, 0, 0, 0xFB}, d.digIn());
    assertArrayEquals(new int[] {0x0F}, d.digOut());
    assertArrayEquals(new int[] {512, 1023}, d.analog());
    IoPacket e = new IoPacket(new int[] {1, 0, 0, 0xFB}, new int[] {0x0F}, new int[] {512, 1023});
    assertBytes(frame, e.encode(new ArRobotPacket()));
  }

  @Test
  void gyroPac() {
    String frame =
        """
        FA FB 0A 98
        02               # two samples
        00 02 19         # rate 512, 25 degrees
        12 02 1A         # rate 530, 26 degrees
        B3 30
        """;
    GyroPacket d = GyroPacket.decode(load(frame));
    assertNotNull(d);
    assertArrayEquals(new int[] {512, 530}, d.rates());
    assertArrayEquals(new int[] {25, 26}, d.temperatures());
    assertBytes(frame, new GyroPacket(new int[] {512, 530}, new int[] {25, 26}).encode(p()));
  }

  @Test
  void simStat() {
    String frame =
        """
        FA FB 38 62
        00 00            # two unused bytes
        05 00 00 00      # flags: map loaded, odometry error fields valid
        0A 00 0A 00 03 00  # sim, real and last interval, ms
        DC 05 00 00      # true x 1500
        3C F6 FF FF      # true y -2500
        00 00 00 00      # true z 0
        A6 FF FF FF      # true th -90
        00 00 00 00 00 00 00 00 00 00 00 00  # latitude, longitude, altitude
        FF               # GPS quality -1 (none)
        40 42 0F 00      # odometry error x 1000000
        80 7B E1 FF      # odometry error y -2000000
        00 00 00 00      # odometry error th 0
        10 93
        """;
    SimStatPacket d = SimStatPacket.decode(load(frame));
    SimStatPacket e =
        new SimStatPacket(5, 10, 10, 3, 1500, -2500, 0, -90, 0, 0, 0, -1, 1_000_000, -2_000_000, 0);
    assertEquals(e, d);
    assertBytes(frame, e.encode(p()));
  }

  @Test
  void configPac() {
    String frame =
        """
        FA FB 7C 20
        50 69 6F 6E 65 65 72 00   # type "Pioneer"
        70 33 64 78 2D 73 68 00   # subtype "p3dx-sh"
        41 42 31 32 00            # serial "AB12"
        00                        # legacy byte
        68 01                     # RotVelTop 360
        98 08                     # TransVelTop 2200
        2C 01                     # RotAccTop 300
        D0 07                     # TransAccTop 2000
        E8 03                     # PwmMax 1000
        52 6F 62 62 69 65 00      # name "Robbie"
        64 00 00                  # SipCycle 100, HostBaud 0, Aux1Baud 0
        01 00                     # HasGripper 1
        01 00                     # FrontSonar 1
        00                        # RearSonar 0
        6E 00                     # LowBattery 110
        BA 40                     # RevCount 16570
        D0 07                     # Watchdog 2000
        01                        # NormalMPacs 1
        FA 00 0A 00               # StallVal 250, StallCount 10
        2C 01 64 00               # JoyVel 300, JoyRotVel 100
        F4 01 D0 04               # RotVelMax 500, TransVelMax 1232
        2C 01 2C 01               # RotAccel 300, RotDecel 300
        70 00 26 00 00 00         # RotKP 112, RotKV 38, RotKI 0
        2C 01 2C 01               # TransAccel 300, TransDecel 300
        28 00 1E 00 00 00         # TransKP 40, TransKV 30, TransKI 0
        05 00 00 28 01 01         # FrontBumps 5, RearBumps 0, HasCharger 0, SonarCycle 40,
                                  # ResetBaud 1, HasGyro 1
        FE FF                     # DriftFactor -2
        00 00                     # Aux2Baud 0, Aux3Baud 0
        0C 00                     # TicksMM 12
        5A 00                     # ShutdownVolts 90
        35 2E 32 00               # firmware version "5.2"
        81 00 7F 00               # GyroCW 129, GyroCCW 127
        00                        # KinematicsDelay 0
        00 00 00 00 00 00 00 00 00 00  # LatVelTop, LatAccelTop, LatVelMax, LatAccel, LatDecel 0
        F4 01                     # ChargeThreshold 500
        F8 71
        """;
    ArConfigPacket d = ArConfigPacket.decode(load(frame));
    assertNotNull(d);
    assertEquals("Pioneer", d.getType());
    assertEquals("p3dx-sh", d.getSubType());
    assertEquals("AB12", d.getSerialNumber());
    assertEquals(360, d.getRotVelTop());
    assertEquals(2200, d.getTransVelTop());
    assertEquals(300, d.getInt(ArConfigPacket.Field.ROT_ACCEL_TOP));
    assertEquals(2000, d.getInt(ArConfigPacket.Field.TRANS_ACCEL_TOP));
    assertEquals(1000, d.getInt(ArConfigPacket.Field.PWM_MAX));
    assertEquals("Robbie", d.getName());
    assertEquals(100, d.getSipCycleTime());
    assertEquals(1, d.getInt(ArConfigPacket.Field.HAS_GRIPPER));
    assertEquals(16570, d.getInt(ArConfigPacket.Field.REV_COUNT));
    assertEquals(2000, d.getWatchdog());
    assertEquals(500, d.getRotVelMax());
    assertEquals(1232, d.getTransVelMax());
    assertEquals(112, d.getInt(ArConfigPacket.Field.ROT_KP));
    assertEquals(30, d.getInt(ArConfigPacket.Field.TRANS_KV));
    assertEquals(40, d.getInt(ArConfigPacket.Field.SONAR_CYCLE));
    assertEquals(1, d.getHasGyro());
    assertEquals(-2, d.getInt(ArConfigPacket.Field.DRIFT_FACTOR));
    assertEquals(12, d.getTicksMM());
    assertEquals(90, d.getInt(ArConfigPacket.Field.SHUTDOWN_VOLTS));
    assertEquals("5.2", d.getFirmwareVersion());
    assertEquals(500, d.getInt(ArConfigPacket.Field.CHARGE_THRESHOLD));
    assertEquals(129, d.getInt(ArConfigPacket.Field.GYRO_CW));
    assertEquals(127, d.getInt(ArConfigPacket.Field.GYRO_CCW));
    assertEquals(0, d.getExtra().length);

    ArConfigPacket e = new ArConfigPacket();
    e.set(ArConfigPacket.Field.TYPE, "Pioneer").set(ArConfigPacket.Field.SUBTYPE, "p3dx-sh");
    e.set(ArConfigPacket.Field.SERIAL_NUMBER, "AB12").set(ArConfigPacket.Field.NAME, "Robbie");
    e.set(ArConfigPacket.Field.FIRMWARE_VERSION, "5.2");
    int[][] ints = {
      {ArConfigPacket.Field.ROT_VEL_TOP.ordinal(), 360},
      {ArConfigPacket.Field.TRANS_VEL_TOP.ordinal(), 2200},
      {ArConfigPacket.Field.ROT_ACCEL_TOP.ordinal(), 300},
      {ArConfigPacket.Field.TRANS_ACCEL_TOP.ordinal(), 2000},
      {ArConfigPacket.Field.PWM_MAX.ordinal(), 1000},
      {ArConfigPacket.Field.SIP_CYCLE_TIME.ordinal(), 100},
      {ArConfigPacket.Field.HAS_GRIPPER.ordinal(), 1},
      {ArConfigPacket.Field.FRONT_SONAR.ordinal(), 1},
      {ArConfigPacket.Field.LOW_BATTERY.ordinal(), 110},
      {ArConfigPacket.Field.REV_COUNT.ordinal(), 16570},
      {ArConfigPacket.Field.WATCHDOG.ordinal(), 2000},
      {ArConfigPacket.Field.NORMAL_MPACS.ordinal(), 1},
      {ArConfigPacket.Field.STALL_VAL.ordinal(), 250},
      {ArConfigPacket.Field.STALL_COUNT.ordinal(), 10},
      {ArConfigPacket.Field.JOY_VEL.ordinal(), 300},
      {ArConfigPacket.Field.JOY_ROT_VEL.ordinal(), 100},
      {ArConfigPacket.Field.ROT_VEL_MAX.ordinal(), 500},
      {ArConfigPacket.Field.TRANS_VEL_MAX.ordinal(), 1232},
      {ArConfigPacket.Field.ROT_ACCEL.ordinal(), 300},
      {ArConfigPacket.Field.ROT_DECEL.ordinal(), 300},
      {ArConfigPacket.Field.ROT_KP.ordinal(), 112},
      {ArConfigPacket.Field.ROT_KV.ordinal(), 38},
      {ArConfigPacket.Field.TRANS_ACCEL.ordinal(), 300},
      {ArConfigPacket.Field.TRANS_DECEL.ordinal(), 300},
      {ArConfigPacket.Field.TRANS_KP.ordinal(), 40},
      {ArConfigPacket.Field.TRANS_KV.ordinal(), 30},
      {ArConfigPacket.Field.FRONT_BUMPS.ordinal(), 5},
      {ArConfigPacket.Field.SONAR_CYCLE.ordinal(), 40},
      {ArConfigPacket.Field.RESET_BAUD.ordinal(), 1},
      {ArConfigPacket.Field.HAS_GYRO.ordinal(), 1},
      {ArConfigPacket.Field.DRIFT_FACTOR.ordinal(), -2},
      {ArConfigPacket.Field.TICKS_MM.ordinal(), 12},
      {ArConfigPacket.Field.SHUTDOWN_VOLTS.ordinal(), 90},
      {ArConfigPacket.Field.CHARGE_THRESHOLD.ordinal(), 500},
      {ArConfigPacket.Field.GYRO_CW.ordinal(), 129},
      {ArConfigPacket.Field.GYRO_CCW.ordinal(), 127},
    };
    for (int[] kv : ints) {
      e.set(ArConfigPacket.Field.values()[kv[0]], kv[1]);
    }
    assertBytes(frame, e.encode(p()));
  }

  @Test
  void joystickPac() {
    String frame =
        """
        FA FB 0B F8
        01 00            # button 0 pressed, button 1 not
        00 02 FF 03      # X 512, Y 1023
        2C 01            # throttle 300
        FE 2D
        """;
    JoystickPacket e = new JoystickPacket(1, 0, 512, 1023, 300);
    assertEquals(e, JoystickPacket.decode(load(frame)));
    assertBytes(frame, e.encode(p()));
  }

  @Test
  void gripperPac() {
    String frame =
        """
        FA FB 06 E0
        01               # a Pioneer gripper
        11               # GRIP_STATE: paddles open (bit 0), lift up (bit 4)
        05               # grasp time
        F1 06
        """;
    GripperPacket e = new GripperPacket(1, 0x11, 5);
    assertEquals(e, GripperPacket.decode(load(frame)));
    assertBytes(frame, e.encode(p()));
  }

  /**
   * The spec lists TCM2pac's fields from pitch on; ARIA's compass reader (the reference client)
   * reads the heading, in tenths of a degree, before them, and so does this codec.
   */
  @Test
  void tcm2Pac() {
    String frame =
        """
        FA FB 17 C0
        D2 04            # heading 123.4 degrees
        F1 FF 14 00      # pitch -1.5, roll 2.0 degrees
        64 00 38 FF 2C 01  # magnetic field X 100, Y -200, Z 300
        EB 00            # temperature 23.5
        00 00            # error bits
        09 08            # H and V calibration scores
        96 00            # M score 150
        CF 29
        """;
    Tcm2Packet e = new Tcm2Packet(1234, -15, 20, 100, -200, 300, 235, 0, 9, 8, 150);
    assertEquals(e, Tcm2Packet.decode(load(frame)));
    assertBytes(frame, e.encode(p()));
  }

  @Test
  void serAuxPacs() {
    String aux1 = "FA FB 06 B0  68 69 0D  19 75"; // "hi\r" from AUX1
    String aux3 = "FA FB 06 C8  68 69 0D  31 75"; // the same from AUX3
    byte[] hi = {'h', 'i', '\r'};
    assertEquals(new SerAuxPacket(1, hi), SerAuxPacket.decode(load(aux1)));
    assertEquals(new SerAuxPacket(3, hi), SerAuxPacket.decode(load(aux3)));
    assertBytes(aux1, new SerAuxPacket(1, hi).encode(p()));
    assertBytes(aux3, new SerAuxPacket(3, hi).encode(p()));
  }

  private static ArRobotPacket p() {
    return new ArRobotPacket();
  }
}
