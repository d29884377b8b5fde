package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SerAuxPacket;
import org.jaria.sim.serial.Vcc4Camera;
import org.junit.jupiter.api.Test;

/**
 * Bytes real ARIA programs (AriaCoda's {@code wander} and {@code cameraPTZExample}, recorded with
 * socat between them and {@code ./jaria sim}) replayed against a default simulated P3-DX, with the
 * answers checked the way ARIA reads them. The hand-run suite in {@code conformance/} found what
 * these tests keep fixed.
 */
class AriaPeerReplayTest {

  private static final SimOptions OPTS = SimOptions.builder().watchdogMillis(0).build();
  private static final HexFormat HEX = HexFormat.of();

  /** What ARIA's ArSimulatedLaser::blockingConnect sends: 36 −90, 37 90, 38 100, 35 2. */
  private static final String[] ARIA_LASER_CONNECT = {
    "fafb06241b5a007e1b", "fafb06253b5a007f3b", "fafb06263b64008a3b", "fafb06233b0200253b",
  };

  @Test
  void ariaWanderConnectsToTheLaserOfADefaultP3dxWithNothingItCannotRead() {
    try (SimWorld w = SimWorld.bundled("office", OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.clear();
      for (String p : ARIA_LASER_CONNECT) {
        c.sendRaw(HEX.parseHex(p));
      }
      w.advanceMillis(2000);
      AriaSimLaserReader aria = new AriaSimLaserReader();
      Set<Integer> ids = new TreeSet<>();
      for (ArRobotPacket p : c.all()) {
        ids.add(p.getID());
        aria.handle(p);
      }
      assertTrue(aria.scans >= 19, "a scan every SIP cycle from the first: " + aria.scans);
      assertEquals(0, aria.tooManyReadings, "ARIA's 'too many readings, popping one'");
      assertEquals(181, aria.lastTotal, "-90..90 at 1 degree");
      assertEquals(List.of(0, 32, 64, 96, 128, 160), aria.firstScanStarts);
      ids.removeIf(PacketIds::isStandardSip);
      assertEquals(Set.of(PacketIds.SIM_LASER_EXTENDED), ids, "no gripper packets (0xE0) etc.");
    }
  }

  /**
   * ARIA's {@code demo} sets the laser up and then, through its ArGripper, sends GRIPPERPACREQUEST
   * 2 (37, the SRISim number of "laser end angle"). Read as a laser command, as MobileSim does, it
   * narrowed the laser to −90..2° and ARIA printed "too many readings, popping one" 176 times (88
   * for each of its two buffers); outside the set-up sequence it must stay a gripper request.
   */
  @Test
  void ariaDemosGripperRequestAfterTheLaserSetUpLeavesTheLaserAlone() {
    try (SimWorld w = SimWorld.bundled("office", OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.clear();
      for (String p : ARIA_LASER_CONNECT) {
        c.sendRaw(HEX.parseHex(p));
      }
      w.advanceMillis(500);
      c.sendRaw(HEX.parseHex("fafb06253b0200273b")); // 37 2: GRIPPERPACREQUEST, continuous
      w.advanceMillis(1500);
      AriaSimLaserReader aria = new AriaSimLaserReader();
      for (ArRobotPacket p : c.all()) {
        aria.handle(p);
      }
      assertEquals(0, aria.tooManyReadings, "ARIA's 'too many readings, popping one'");
      assertEquals(181, aria.lastTotal, "the field of view is still -90..90");
      assertTrue(c.packets(PacketIds.GRIPPER).size() >= 10, "GRIPPERpac every cycle");
    }
  }

  /**
   * ARIA's ArVCC4 initialising and polling a VC-C4 on AUX1: GETAUX 0 (flush), then before each
   * command GETAUX 6; a position request is followed by GETAUX for the rest once the first six
   * bytes show no footer.
   */
  @Test
  void ariaVcc4GetsTheCamerasAnswersByteForByte() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.clear();
      byte[] ok = HEX.parseHex("fe30303030ef");
      c.sendRaw(HEX.parseHex("fafb062b3b00002b3b")); // GETAUX 0
      for (String tty2 :
          List.of(
              "fafb0c2a2b07ff303000a031ef94e9", // power on
              "fafb0c2a2b07ff3030009030ef93d9", // host control mode
              "fafb0c2a2b07ff3030005830ef93a1", // pedestal initialise
              "fafb0e2a2b09ff30300050333230efc8cb", // pan slew 320h
              "fafb0e2a2b09ff30300051323635efccd0", // tilt slew 265h
              "fafb142a2b0fff30300064313745463538333045ef8f92", // tilt range 7EF5..830E
              "fafb132a2b0eff303000623743453038303030ef4e60")) { // pan -90, tilt 0
        assertArrayEquals(ok, exchange(w, c, "fafb062b3b0600313b", tty2), tty2);
      }
      byte[] first = exchange(w, c, "fafb062b3b0600313b", "fafb0b2a2b06ff30300063ef6152");
      assertEquals(0xFE, first[0] & 0xFF);
      assertTrue(first[5] != (byte) 0xEF, "no footer yet: ARIA asks for the other 8 bytes");
      byte[] rest = exchange(w, c, "fafb062b3b0800333b", null);
      assertEquals(0x37, first[5], "pan starts 7...");
      assertArrayEquals(HEX.parseHex("43453038303030ef"), rest, "pan 7CE0 (-90), tilt 8000");
      byte[] z = exchange(w, c, "fafb062b3b0600313b", "fafb0c2a2b07ff303000b430ef93fd");
      assertEquals(6, z.length);
      assertArrayEquals(
          HEX.parseHex("303030ef"), exchange(w, c, "fafb062b3b04002f3b", null), "zoom 0");
      Vcc4Camera camera = (Vcc4Camera) r.body().auxPort(1).device();
      assertEquals(-90, camera.getPan(), 0.06, "the head turned");
    }
  }

  /** Sends GETAUX {@code request} then the TTY2 {@code command} (if any); returns the answer. */
  private static byte[] exchange(SimWorld w, ArcosTestClient c, String request, String command) {
    c.clear();
    c.sendRaw(HEX.parseHex(request));
    if (command != null) {
      c.sendRaw(HEX.parseHex(command));
    }
    w.advanceMillis(100);
    List<ArRobotPacket> got = c.packets(PacketIds.SERAUX1);
    assertEquals(1, got.size(), "one SERAUXpac per request");
    return SerAuxPacket.decode(got.get(0)).data();
  }

  /**
   * The bookkeeping of ARIA's {@code ArSimulatedLaser::simPacketHandler}: the readings list it
   * assembles a scan in, trimmed (with the "too many readings" warning) when a packet's total is
   * smaller than the list, and the two buffers it swaps on every completed scan.
   */
  private static final class AriaSimLaserReader {
    int assembleSize;
    int currentSize;
    int tooManyReadings;
    int scans;
    int lastTotal;
    final List<Integer> firstScanStarts = new ArrayList<>();

    void handle(ArRobotPacket p) {
      if (p.getID() != PacketIds.SIM_LASER && p.getID() != PacketIds.SIM_LASER_EXTENDED) {
        return;
      }
      p.resetRead();
      if (p.getID() == PacketIds.SIM_LASER) {
        p.skip(6);
      }
      int total = p.bufToUByte2();
      int first = p.bufToUByte2();
      int n = p.bufToUByte();
      while (assembleSize > total) {
        tooManyReadings++;
        assembleSize--;
      }
      if (assembleSize == 0) {
        assembleSize = total;
      }
      if (scans == 0) {
        firstScanStarts.add(first);
      }
      int per = p.getID() == PacketIds.SIM_LASER_EXTENDED ? 5 : 2;
      assertTrue(p.isNextGood(per * n), "the packet holds its " + n + " readings");
      lastTotal = total;
      if (first + n >= total) {
        int t = assembleSize;
        assembleSize = currentSize;
        currentSize = t;
        scans++;
      }
    }
  }
}
