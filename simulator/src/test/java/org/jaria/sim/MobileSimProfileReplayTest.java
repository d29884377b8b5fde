package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.robot.SimProfile;
import org.junit.jupiter.api.Test;

/**
 * What AMRISim (MobileSim's successor) sent AriaCoda's {@code demo}, recorded with {@code socat -x}
 * between them (conformance/side-by-side.sh; AMRISim's office map, one {@code p3dx} at its dock,
 * and a second run with {@code --start outside}), and what JAria's {@code mobilesim} profile sends
 * for the same requests. The bytes that depend on the place (positions, ranges) differ; everything
 * a program reads about the robot itself must not.
 */
class MobileSimProfileReplayTest {

  private static final HexFormat HEX = HexFormat.of();

  private static final SimOptions MOBILESIM =
      SimOptions.builder().profile(SimProfile.MOBILESIM).build();

  private static final SimOptions PIONEER = SimOptions.defaults();

  /** AMRISim's SYNC2: its name, the class and the subtype. */
  static final String AMRISIM_SYNC2 = "fafb1802414d524953696d0050696f6e656572007033647800ebbd";

  /** AMRISim's CONFIGpac for a p3dx, in answer to ARIA's CONFIG right after OPEN. */
  static final String AMRISIM_CONFIG =
      "fafb792050696f6e65657200703364780053494d00000f270f270f270f279001414d524953696d0064000000"
          + "0001000100000000d0070000000000000000009600b80b640064000000000000002c012c0100000000000000"
          + "00000002000000000000000000532e300000000000000f270f270000000000000000935f";

  /**
   * AMRISim's first SIP, before the program sent ENABLE: motors on (flags 0x1F), 16 sonar readings,
   * DIGIN and DIGOUT 0xFF, 13.0 V, temperature -127 ("none"), state of charge 0.
   */
  static final String AMRISIM_FIRST_SIP =
      "fafb56320000000000000000000082000000001f000010003906019c0d02f00a034d0704881305631206de1107"
          + "4e0408c0030945030a68030b27020c16020ddf030ebf030f5305000000ffff820000000000000000810087"
          + "16";

  /** AMRISim's first laser packet of a scan from outside the map: 0x7FFF where nothing echoes. */
  static final String AMRISIM_LASER_OUTSIDE =
      "fafbaa61b500000020ff7f000000ff7f000000ff7f000000ff7f000000ff7f000000266d0000008554000000c054"
          + "000000f5540000000955000000665500000039550000001a55000000fd54000000f64c000000924b0000"
          + "000547000000e1420000002f3f000000f33b000000f2380000006a3600000027340000000d320000005a30"
          + "0000005229000000a429000000092a0000003b2a000000f428000000c9270000007c2600000000003957";

  /** What AriaCoda's ArRobot sends after SYNC2, up to and including its laser set-up. */
  static final String[] ARIA_AFTER_SYNC2 = {
    "fafb06013b0100023b", // OPEN
    "fafb06123b0100133b", // CONFIG
    "fafb063e3b01003f3b", // 62 1
    "fafb061f3b010b2046", // 31
    "fafb06063bb80bbe46", // SETV 3000
    "fafb06053b2c01313c", // SETA 300
    "fafb06051b2c01311c", // SETA -300
    "fafb060a3b9600a03b", // SETRV 150
    "fafb06173b64007b3b", // SETRA 100
    "fafb06171b64007b1b", // SETRA -100
    "fafb06241b5a007e1b", // laser start -90
    "fafb06253b5a007f3b", // laser end 90
    "fafb06263b64008a3b", // increment 1
    "fafb06233b0200253b", // laser on, extended packets
  };

  private static ArRobotPacket packet(String hex) {
    byte[] b = HEX.parseHex(hex);
    ArRobotPacket p = new ArRobotPacket().load(b, 0, b.length);
    assertTrue(p.verifyCheckSum(), "a recorded packet");
    return p;
  }

  /** Handshake and ARIA's requests, as recorded; returns the client with everything received. */
  private static ArcosTestClient ariaConnects(SimWorld w, SimRobot r) {
    ArcosTestClient c = new ArcosTestClient(w, r);
    for (int sync = 0; sync < 3; sync++) {
      c.com(sync);
      c.awaitId(sync);
    }
    for (String cmd : ARIA_AFTER_SYNC2) {
      c.sendRaw(HEX.parseHex(cmd));
    }
    w.advanceMillis(500);
    return c;
  }

  @Test
  void configPacHasMobileSimsValuesFieldByField() {
    ArConfigPacket amrisim = ArConfigPacket.decode(packet(AMRISIM_CONFIG));
    try (SimWorld w = SimWorld.empty(MOBILESIM)) {
      ArcosTestClient c = ariaConnects(w, w.addRobot("p3dx"));
      ArConfigPacket jaria = ArConfigPacket.decode(c.packets(PacketIds.CONFIG).get(0));
      for (ArConfigPacket.Field f : ArConfigPacket.Field.values()) {
        if (f == ArConfigPacket.Field.NAME) {
          continue; // AMRISim says its own name; JAria says MobileSim's, as ARIA 2.9.1 needs
        }
        assertEquals(amrisim.has(f), jaria.has(f), f.toString());
        if (f.isString()) {
          assertEquals(amrisim.getString(f), jaria.getString(f), f.toString());
        } else {
          assertEquals(amrisim.getInt(f), jaria.getInt(f), f.toString());
        }
      }
      assertEquals("S.0", jaria.getFirmwareVersion());
      assertEquals(amrisim.getExtra().length, jaria.getExtra().length, "nothing after the fields");
      assertEquals("MobileSim", jaria.getName());
    }
  }

  @Test
  void thePioneerProfileKeepsTheParameterFilesConfiguration() {
    try (SimWorld w = SimWorld.empty(PIONEER)) {
      ArcosTestClient c = ariaConnects(w, w.addRobot("p3dx"));
      ArConfigPacket jaria = ArConfigPacket.decode(c.packets(PacketIds.CONFIG).get(0));
      assertEquals(1500, jaria.getTransVelMax());
      assertEquals(300, jaria.getRotVelMax());
      assertNotEquals(9999, jaria.getTransVelTop());
      assertEquals("S.1", jaria.getFirmwareVersion());
      assertEquals(0, jaria.getInt(ArConfigPacket.Field.GYRO_CW), "the string no longer runs in");
    }
  }

  @Test
  void handshakeNamesTheClassAndSubtypeAsMobileSimDoes() {
    ArRobotPacket amrisim = packet(AMRISIM_SYNC2);
    try (SimWorld w = SimWorld.empty(MOBILESIM)) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx"));
      for (int sync = 0; sync < 3; sync++) {
        c.com(sync);
        c.awaitId(sync);
      }
      ArRobotPacket jaria = c.packets(2).get(0);
      amrisim.resetRead();
      jaria.resetRead();
      assertEquals("AMRISim", amrisim.bufToString());
      assertEquals("MobileSim", jaria.bufToString(), "the name ARIA 2.9.1 knows a simulator by");
      assertEquals(amrisim.bufToString(), jaria.bufToString(), "class");
      assertEquals(amrisim.bufToString(), jaria.bufToString(), "subtype");
    }
  }

  @Test
  void firstSipHasMobileSimsLayoutMotorsOnAndAllSixteenSonar() {
    StandardSip amrisim = new StandardSip();
    assertTrue(amrisim.decode(packet(AMRISIM_FIRST_SIP)));
    try (SimWorld w = SimWorld.bundled("office", MOBILESIM)) {
      ArcosTestClient c = ariaConnects(w, w.addRobot("p3dx"));
      List<ArRobotPacket> sips = new ArrayList<>();
      for (ArRobotPacket p : c.all()) {
        if (PacketIds.isStandardSip(p.getID())) {
          sips.add(p);
        }
      }
      ArRobotPacket first = sips.get(0);
      StandardSip jaria = new StandardSip();
      assertTrue(jaria.decode(first));
      assertEquals(packet(AMRISIM_FIRST_SIP).getLength(), first.getLength(), "same layout");
      assertEquals(amrisim.getId(), jaria.getId());
      assertEquals(amrisim.getFlags(), jaria.getFlags(), "motors on, all sonar arrays on");
      assertEquals(amrisim.getOptionalCount(), jaria.getOptionalCount());
      assertEquals(amrisim.getBattery(), jaria.getBattery());
      assertEquals(amrisim.getBatteryX10(), jaria.getBatteryX10());
      assertEquals(amrisim.getDigIn(), jaria.getDigIn());
      assertEquals(amrisim.getDigOut(), jaria.getDigOut());
      assertEquals(amrisim.getGripState(), jaria.getGripState());
      assertEquals(amrisim.getTemperature(), jaria.getTemperature());
      assertEquals(amrisim.getSoc(), jaria.getSoc());
      assertEquals(amrisim.getControl(), jaria.getControl());
      for (ArRobotPacket p : sips) {
        StandardSip s = new StandardSip();
        s.decode(p);
        assertEquals(16, s.getSonarCount(), "every SIP carries every transducer");
        for (int i = 0; i < 16; i++) {
          assertEquals(amrisim.getSonarNumber(i), s.getSonarNumber(i));
        }
      }
    }
  }

  @Test
  void thePioneerProfileStartsWithMotorsOffAndAFewSonarReadingsPerSip() {
    try (SimWorld w = SimWorld.bundled("office", PIONEER)) {
      ArcosTestClient c = ariaConnects(w, w.addRobot("p3dx"));
      StandardSip first = c.sips().get(0);
      assertEquals(0x1E, first.getFlags(), "sonar on, motors off until ENABLE");
      for (StandardSip s : c.sips()) {
        assertTrue(s.getSonarCount() <= 6, "a sonar cycle's worth: " + s.getSonarCount());
      }
    }
  }

  @Test
  void aBeamWithNoEchoReadsWhatMobileSimSendsAndAriaDrops() {
    ArRobotPacket amrisim = packet(AMRISIM_LASER_OUTSIDE);
    amrisim.resetRead();
    amrisim.skip(5);
    assertEquals(LaserModel.NO_ECHO_MM, amrisim.bufToUByte2(), "AMRISim's first beam: no echo");
    for (SimOptions o : List.of(MOBILESIM, PIONEER)) {
      try (SimWorld w = SimWorld.bundled("office", o)) {
        // far outside the office, facing away from it: no beam meets anything
        SimRobot r = w.addRobot(RobotOptions.of("p3dx").withStartPose(new ArPose(-90000, 0, 180)));
        ArcosTestClient c = ariaConnects(w, r);
        List<ArRobotPacket> scan = c.packets(PacketIds.SIM_LASER_EXTENDED);
        assertTrue(scan.size() >= 6, "a whole scan");
        int kept = 0;
        int dropped = 0;
        for (ArRobotPacket p : scan.subList(0, 6)) {
          p.resetRead();
          p.skip(4);
          int n = p.bufToUByte();
          for (int k = 0; k < n; k++) {
            int range = p.bufToUByte2();
            p.skip(3);
            assertEquals(LaserModel.NO_ECHO_MM, range, o.profile() + ": no echo");
            // ArSimulatedLaser ignores a range above its laser's 32000 mm
            if (range > 32000) {
              dropped++;
            } else {
              kept++;
            }
          }
        }
        assertEquals(0, kept, o.profile() + ": ARIA keeps no phantom reading");
        assertEquals(181, dropped);
      }
    }
  }

  @Test
  void mobileSimsMotorsAreOnForTheFirstSessionAndOffAfterItEnds() {
    try (SimWorld w = SimWorld.empty(MOBILESIM)) {
      SimRobot r = w.addRobot("p3dx");
      assertTrue(r.areMotorsEnabled(), "on when the robot is made");
      ArcosTestClient c = ariaConnects(w, r);
      c.conn.close();
      w.advanceMillis(200);
      assertTrue(!r.areMotorsEnabled(), "a session's end turns them off, as in MobileSim");
    }
    try (SimWorld w = SimWorld.empty(PIONEER)) {
      assertTrue(!w.addRobot("p3dx").areMotorsEnabled(), "a real Pioneer waits for ENABLE");
    }
  }
}
