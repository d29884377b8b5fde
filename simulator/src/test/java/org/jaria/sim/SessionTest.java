package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.Hex;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SimStatPacket;
import org.jaria.sim.server.IgnoredCommand;
import org.junit.jupiter.api.Test;

/** The ARCOS session: handshake bytes, watchdog, simulator commands, bad input. */
class SessionTest {

  private static SimOptions opts(int watchdog) {
    return SimOptions.builder().watchdogMillis(watchdog).build();
  }

  @Test
  void handshakeEchoesSyncsAndSync2CarriesNameTypeSubtype() {
    try (SimWorld w = SimWorld.empty(opts(2000))) {
      SimRobot r = w.addRobot("p3at-sh");
      ArcosTestClient c = new ArcosTestClient(w, r);
      c.sendRaw(Hex.parse("FA FB 03 00 00 00"));
      w.step();
      assertEquals("FA FB 03 00 00 00", Hex.format(c.rawIn.toByteArray()));
      c.rawIn.reset();
      c.sendRaw(Hex.parse("FA FB 03 01 00 01"));
      w.step();
      assertEquals("FA FB 03 01 00 01", Hex.format(c.rawIn.toByteArray()));
      c.rawIn.reset();
      c.sendRaw(Hex.parse("FA FB 03 02 00 02"));
      w.step();
      ArRobotPacket expected = new ArRobotPacket(ArCommands.SYNC2);
      expected.strToBuf("MobileSim").strToBuf("Pioneer").strToBuf("p3at-sh").finalizePacket();
      assertArrayEquals(expected.toByteArray(), c.rawIn.toByteArray());
      c.rawIn.reset();
      w.advanceMillis(500);
      assertEquals(0, c.rawIn.size(), "no SIPs before OPEN");
      c.comInt(ArCommands.OPEN, 1);
      w.step();
      assertTrue(c.rawIn.size() > 0);
      assertTrue(PacketIds.isStandardSip(c.received.get(c.received.size() - 1).getID()));
    }
  }

  @Test
  void sipsComeEverySipCycle() {
    try (SimWorld w = SimWorld.empty(opts(0).toBuilder().sipCycleMillis(50).build())) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.clear();
      w.advanceMillis(1000);
      assertEquals(20, c.sips().size());
    }
  }

  @Test
  void syncInAnOpenSessionIsAPulseSoAReconnectingClientClosesAndStartsOver() {
    try (SimWorld w = SimWorld.empty(opts(2000))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient first = new ArcosTestClient(w, r).open();
      first.comInt(ArCommands.VEL, 200);
      w.advanceMillis(300);
      // The first client vanishes without CLOSE; the watchdog stops the robot.
      w.advanceMillis(4000);
      assertEquals(0, r.getVel(), 1e-9);
      first.clear();
      first.com(ArCommands.SYNC0); // a new client program on the same line
      ArRobotPacket answer = first.awaitPacket(p -> true, 20);
      assertEquals(PacketIds.SIP_STOPPED, answer.getID(), "an open robot answers SYNC0 with a SIP");
      first.comInt(ArCommands.CLOSE, 1); // as ARIA sends it
      w.advanceMillis(300);
      first.clear();
      w.advanceMillis(500);
      assertTrue(first.received.isEmpty(), "no SIPs after CLOSE");
      assertFalse(r.isSessionOpen());
      for (int s = 0; s < 3; s++) {
        first.com(s);
        assertEquals(s, first.awaitPacket(p -> true, 20).getID());
      }
      first.comInt(ArCommands.OPEN, 1);
      first.awaitPacket(p -> PacketIds.isStandardSip(p.getID()), 20);
      assertTrue(r.isSessionOpen());
      assertFalse(r.areMotorsEnabled(), "motors start disabled in every session");
    }
  }

  @Test
  void outOfSequenceSyncIsIgnoredAndSync0Restarts() {
    try (SimWorld w = SimWorld.empty(opts(2000))) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh"));
      c.com(ArCommands.SYNC1);
      w.advanceMillis(100);
      assertTrue(c.received.isEmpty());
      c.com(ArCommands.SYNC0);
      assertEquals(0, c.awaitPacket(p -> true, 5).getID());
      c.com(ArCommands.SYNC2);
      w.advanceMillis(100);
      assertEquals(1, c.received.size(), "SYNC2 before SYNC1 gets no answer");
      c.com(ArCommands.SYNC0);
      c.com(ArCommands.SYNC1);
      c.com(ArCommands.SYNC2);
      ArRobotPacket p = c.awaitId(2);
      p.resetRead();
      assertEquals("MobileSim", p.bufToString(), "MobileSim's name: ARIA 2.9.1 needs it");
    }
  }

  @Test
  void watchdogStopsTheRobotAndTheNextCommandResumes() {
    try (SimWorld w = SimWorld.empty(opts(2000))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(1900);
      assertEquals(500, r.getVel(), 1e-9);
      w.advanceMillis(300);
      assertTrue(r.getVel() < 500, "the watchdog decelerates the robot");
      w.advanceMillis(2000);
      assertEquals(0, r.getVel(), 1e-9);
      c.com(ArCommands.PULSE); // keeps the link alive but does not restart the motion
      w.advanceMillis(1000);
      assertEquals(0, r.getVel(), 1e-9);
      c.comInt(ArCommands.SETA, 300); // any other command: the robot resumes its last setpoint
      w.advanceMillis(2000);
      assertEquals(500, r.getVel(), 1e-9, "resumes the last speed");
    }
  }

  @Test
  void watchdogCanOnlyWarn() {
    SimOptions o = opts(1000).toBuilder().watchdogWarnOnly(true).build();
    try (SimWorld w = SimWorld.empty(o)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 300);
      w.advanceMillis(5000);
      assertEquals(300, r.getVel(), 1e-9);
    }
  }

  @Test
  void configPacketDescribesTheSimulatedRobot() {
    try (SimWorld w = SimWorld.empty(opts(2000))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withGyro(true));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.CONFIG, 1);
      ArConfigPacket cfg = ArConfigPacket.decode(c.awaitId(PacketIds.CONFIG));
      assertNotNull(cfg);
      assertEquals("Pioneer", cfg.getType());
      assertEquals("p3dx-sh", cfg.getSubType());
      assertEquals("SIM", cfg.getSerialNumber());
      assertEquals("MobileSim", cfg.getName());
      assertEquals("S.1", cfg.getFirmwareVersion());
      assertEquals(100, cfg.getSipCycleTime());
      assertEquals(2000, cfg.getWatchdog());
      assertEquals(1, cfg.getHasGyro());
      assertEquals(1, cfg.getInt(ArConfigPacket.Field.HAS_GRIPPER));
      assertEquals(2200, cfg.getTransVelTop());
      assertEquals(500, cfg.getRotVelTop());
      assertEquals(5, cfg.getInt(ArConfigPacket.Field.FRONT_BUMPS));
      assertEquals(40, cfg.getInt(ArConfigPacket.Field.SONAR_CYCLE));
    }
  }

  @Test
  void simStatReportsTheTruePoseAndSimSetPoseMovesItWithoutOdometry() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      byte[] pose =
          ByteBuffer.allocate(13)
              .order(ByteOrder.LITTLE_ENDIAN)
              .put((byte) 0)
              .putInt(-3210)
              .putInt(4567)
              .putInt(-45)
              .array();
      c.comPayload(ArCommands.SIM_SET_POSE, pose);
      w.step();
      assertEquals(new ArPose(-3210, 4567, -45), r.getTruePose());
      assertEquals(ArPose.ORIGIN, r.getOdometryPose(), "odometry does not notice");
      c.comInt(ArCommands.SIM_STAT, 1);
      SimStatPacket s = SimStatPacket.decode(c.awaitId(PacketIds.SIMSTAT));
      assertEquals(-3210, s.trueX());
      assertEquals(4567, s.trueY());
      assertEquals(-45, s.trueTh());
      assertEquals(10, s.simInterval());
      c.comInt(ArCommands.SIM_STAT, 2);
      c.clear();
      w.advanceMillis(1000);
      assertEquals(10, c.packets(PacketIds.SIMSTAT).size(), "one before every SIP");
      c.com(ArCommands.SIM_RESET);
      w.step();
      assertEquals(ArPose.ORIGIN, r.getTruePose());
    }
  }

  @Test
  void setoResetsOrSetsOdometry() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(2000);
      c.com(ArCommands.SETO);
      w.step();
      assertTrue(r.getOdometryPose().findDistanceTo(ArPose.ORIGIN) < 10);
      byte[] p32 =
          ByteBuffer.allocate(13)
              .order(ByteOrder.LITTLE_ENDIAN)
              .put((byte) 0)
              .putInt(100_000)
              .putInt(-200)
              .putInt(90)
              .array();
      c.comPayload(ArCommands.SETO, p32);
      w.step();
      assertEquals(100_000, r.getOdometryPose().x(), 10);
      assertEquals(90, r.getOdometryPose().th(), 1e-9);
      byte[] p16 =
          ByteBuffer.allocate(7)
              .order(ByteOrder.LITTLE_ENDIAN)
              .put((byte) 0x3B)
              .putShort((short) 10)
              .putShort((short) 20)
              .putShort((short) -30)
              .array();
      c.comPayload(ArCommands.SETO, p16);
      w.step();
      assertEquals(-30, r.getOdometryPose().th(), 1e-9);
    }
  }

  @Test
  void garbageTruncatedAndCorruptPacketsAreDroppedAndCounted() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      SplittableRandom rng = new SplittableRandom(7);
      byte[] junk = new byte[500];
      for (int i = 0; i < junk.length; i++) {
        junk[i] = (byte) rng.nextInt(256);
      }
      junk[10] = (byte) 0xFA;
      c.sendRaw(junk);
      ArRobotPacket vel = CommandCodec.comInt(new ArRobotPacket(), 11, 300);
      byte[] bad = vel.toByteArray();
      bad[bad.length - 1] ^= 0x55;
      c.sendRaw(bad);
      c.sendRaw(new byte[] {(byte) 0xFA, (byte) 0xFB, 6, 11, 0x3B}); // truncated VEL
      w.advanceMillis(300);
      assertTrue(r.getDropCounters().get(DropReason.BAD_CHECKSUM) >= 1);
      assertTrue(r.getDropCounters().get(DropReason.TIMEOUT) >= 1);
      assertTrue(r.getDropCounters().skippedBytes() > 0);
      assertEquals(0, r.getVel(), 1e-9, "nothing corrupt was executed");
      c.comInt(ArCommands.VEL, 300);
      w.advanceMillis(2000);
      assertEquals(300, r.getVel(), 1e-9, "the session still works");
    }
  }

  @Test
  void unknownCommandsAreIgnoredAndLoggedOnce() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(200, 5);
      c.comInt(200, 6);
      c.com(201);
      w.advanceMillis(100);
      assertEquals(
          List.of(
              new IgnoredCommand(200, "unknown", IgnoredCommand.Reason.UNKNOWN, 2),
              new IgnoredCommand(201, "unknown", IgnoredCommand.Reason.UNKNOWN, 1)),
          w.getIgnoredCommands());
      assertTrue(r.isSessionOpen());
    }
  }

  @Test
  void simExitCallsTheExitHandler() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      AtomicInteger code = new AtomicInteger(-1);
      w.setExitHandler(code::set);
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh")).open();
      c.comInt(ArCommands.SIM_EXIT, 7);
      w.step();
      assertEquals(7, code.get());
    }
  }

  @Test
  void simCtrlLoadsAMapAndTellsTheClient(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
      throws Exception {
    java.nio.file.Path file = dir.resolve("box.map");
    java.nio.file.Files.writeString(
        file,
        """
        2D-Map
        Cairn: RobotHome 5000 5000 90 "" ICON ""
        LINES
        0 0 10000 0
        10000 0 10000 10000
        10000 10000 0 10000
        0 10000 0 0
        DATA
        """);
    SimOptions o =
        SimOptions.builder()
            .watchdogMillis(0)
            .server(SimServerOptions.DEFAULTS.withMapFolder(dir, 1 << 20))
            .build();
    try (SimWorld w = SimWorld.empty(o)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      byte[] name = "box.map".getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
      ByteBuffer b = ByteBuffer.allocate(5 + name.length).order(ByteOrder.LITTLE_ENDIAN);
      b.put((byte) 0x3B).putShort((short) 1).putShort((short) name.length).put(name);
      c.comPayload(ArCommands.SIM_CTRL, b.array());
      w.step();
      w.awaitClientMapLoad();
      ArRobotPacket changed = c.awaitId(PacketIds.SIM_MAP_CHANGED);
      changed.resetRead();
      assertEquals(0, changed.bufToUByte(), "loaded by a client, not the user");
      assertEquals(1, changed.bufToByte(), "a new map was loaded");
      assertEquals("box.map", changed.bufToString());
      assertEquals(new ArPose(5000, 5000, 90), r.getTruePose());
      assertEquals(4000, w.castRay(5000, 6000, 90, 9000), 1e-6, "the new walls are solid");

      byte[] missing = "no/such/file.map".getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
      ByteBuffer m = ByteBuffer.allocate(5 + missing.length).order(ByteOrder.LITTLE_ENDIAN);
      m.put((byte) 0x3B).putShort((short) 1).putShort((short) missing.length).put(missing);
      c.clear();
      c.comPayload(ArCommands.SIM_CTRL, m.array());
      w.step();
      w.awaitClientMapLoad();
      ArRobotPacket failed = c.awaitId(PacketIds.SIM_MAP_CHANGED);
      failed.resetRead();
      failed.bufToUByte();
      assertEquals(-1, failed.bufToByte(), "status -1: the map could not be loaded");
      assertTrue(r.isSessionOpen());
    }
  }

  @Test
  void simInfoListsTheDevices() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      ArcosTestClient c =
          new ArcosTestClient(w, w.addRobot(RobotOptions.of("p3dx-sh").withLaser(true))).open();
      ByteBuffer b = ByteBuffer.allocate(3).order(ByteOrder.LITTLE_ENDIAN);
      b.put((byte) 0x3B).putShort((short) 6);
      c.comPayload(ArCommands.SIM_CTRL, b.array());
      ArRobotPacket info = c.awaitId(PacketIds.SIMINFO);
      info.resetRead();
      assertEquals("JAriaSim", info.bufToString());
      info.bufToString();
      info.bufToUByte4();
      assertEquals(2, info.bufToUByte4());
    }
  }

  @Test
  void obstaclesCanBeInjectedAndRemoved() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimObstacle box = w.injectBox(3000, 0, 1000, 1000, 0);
      assertEquals(2500, w.castRay(0, 0, 0, 10_000), 1e-9);
      SimObstacle wall = w.injectObstacle(new ArLineSegment(1000, -100, 1000, 100));
      assertEquals(1000, w.castRay(0, 0, 0, 10_000), 1e-9);
      assertTrue(w.removeObstacle(wall));
      assertFalse(w.removeObstacle(wall));
      assertEquals(2500, w.castRay(0, 0, 0, 10_000), 1e-9);
      assertTrue(w.removeObstacle(box));
      assertEquals(Double.POSITIVE_INFINITY, w.castRay(0, 0, 0, 10_000));
      assertEquals(List.of(), w.getObstacles());
    }
  }

  @Test
  void droppingTheConnectionStopsTheRobot() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 400);
      w.advanceMillis(2000);
      r.dropConnection();
      assertFalse(r.isClientConnected());
      w.advanceMillis(100);
      assertEquals(0, r.getVel(), 1e-9);
      assertFalse(r.areMotorsEnabled());
      ArcosTestClient again = new ArcosTestClient(w, r).open();
      assertTrue(r.isSessionOpen());
      assertTrue(again.sips().size() > 0);
      assertEquals(2, r.getSessionCount());
    }
  }

  @Test
  void snapshotDescribesEveryRobot() {
    try (SimWorld w = SimWorld.empty(opts(0))) {
      SimRobot a = w.addRobot("p3dx-sh");
      w.addRobot(RobotOptions.of("amigo").withName("amy"));
      new ArcosTestClient(w, a).open();
      w.advanceMillis(500);
      SimSnapshot s = w.snapshot();
      assertEquals(2, s.robots().size());
      SimSnapshot.RobotView v = s.robots().get(0);
      assertEquals(4, v.footprint().size());
      assertEquals(16, v.sonar().size());
      assertTrue(v.sessionOpen());
      assertEquals("amy", s.robots().get(1).name());
      assertEquals(8, s.robots().get(1).sonar().size());
      assertFalse(
          a.getTruePose().isNear(s.robots().get(1).truePose(), 300, 360),
          "the second robot was placed clear of the first");
      List<String> subtypes = new ArrayList<>();
      s.robots().forEach(x -> subtypes.add(x.subtype()));
      assertEquals(List.of("p3dx-sh", "amigo"), subtypes);
    }
  }
}
