package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.GripperPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.SerAuxPacket;
import org.jaria.sim.robot.LaserModel;
import org.jaria.sim.server.IgnoredCommand;
import org.junit.jupiter.api.Test;

/**
 * What the simulated robot makes of commands whose meaning depends on its devices or that it does
 * not simulate: 35–38 (ARCOS meanings, or the old laser set-up ones when asked for), ROTATE,
 * GETAUX, and the commands it records as ignored.
 */
class CommandMeaningsTest {

  private static final SimOptions OPTS = SimOptions.builder().watchdogMillis(0).build();

  private static RobotOptions laserAndGripper() {
    return RobotOptions.of("p3dx-sh").withLaser(true).withGripper(true);
  }

  @Test
  void withoutSrisimLaserCompatibility35To38MeanWhatTheyMeanOnArcos() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot(laserAndGripper().withLegacyLaserCommands(false));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      LaserModel laser = r.body().laser();

      c.comInt(ArCommands.GRIPPERVAL, 77);
      c.comInt(ArCommands.GRIPPER, 16); // grasp pressure from GRIPPERVAL
      c.comInt(ArCommands.GRIPREQUEST, 1);
      GripperPacket g = GripperPacket.decode(c.awaitId(PacketIds.GRIPPER));
      assertEquals(1, g.hasGripper(), "GRIPREQUEST answered with a GRIPPERpac");
      assertEquals(77, g.graspTime(), "GRIPPERVAL reached the gripper");

      r.setAnalog(3, 800);
      c.comInt(ArCommands.ADSEL, 3);
      c.comInt(ArCommands.GYROCALCW, 1234);
      c.comInt(ArCommands.CONFIG, 1);
      ArConfigPacket cfg = ArConfigPacket.decode(c.awaitId(PacketIds.CONFIG));
      assertEquals(1234, cfg.getInt(ArConfigPacket.Field.GYRO_CW));
      w.advanceMillis(200);
      assertEquals(3, c.lastSip().getAnPort(), "ADSEL selected the analog port");
      assertEquals(800 >> 2, c.lastSip().getAnalog());

      assertEquals(-90, laser.getStart(), 1e-9, "the laser's field of view is untouched");
      assertEquals(1, laser.getIncrement(), 1e-9);
      assertEquals(181, laser.readingCount());
      assertTrue(c.packets(PacketIds.SIM_LASER).isEmpty(), "ADSEL did not switch the laser on");
      assertTrue(c.packets(PacketIds.SIM_LASER_EXTENDED).isEmpty());
      assertEquals(List.of(), w.getIgnoredCommands());
    }
  }

  @Test
  void aDefaultP3dxTakes35To38AsTheSrisimLaserCommandsAsMobileSimDoes() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      LaserModel laser = r.body().laser();
      c.comInt(ArCommands.GRIPPERVAL, -30); // start angle
      c.comInt(ArCommands.GRIPREQUEST, 30); // end angle
      c.comInt(ArCommands.GYROCALCW, 200); // increment 2.00 degrees
      c.comInt(ArCommands.ADSEL, 1); // laser on
      c.clear();
      w.advanceMillis(100);
      assertEquals(-30, laser.getStart(), 1e-9);
      assertEquals(2, laser.getIncrement(), 1e-9);
      assertEquals(31, laser.readingCount(), "-30..30 every 2 degrees");
      assertTrue(c.packets(PacketIds.GRIPPER).isEmpty(), "37 was not a GRIPREQUEST");
      List<ArRobotPacket> scans = c.packets(PacketIds.SIM_LASER);
      assertEquals(1, scans.size(), "one SIP, one scan: 31 readings fit in one packet");
      ArRobotPacket p = scans.get(0);
      p.resetRead();
      p.skip(6); // odometry pose
      assertEquals(31, p.bufToUByte2(), "readings in the scan");
    }
  }

  @Test
  void legacyLaserCommandsNeedALaser() {
    assertFalse(RobotOptions.of("amigo").laser(), "MobileSim's amigo has no laser");
    assertFalse(RobotOptions.of("amigo").legacyLaserCommands());
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class,
            () -> RobotOptions.of("amigo").withLegacyLaserCommands(true));
    assertTrue(e.getMessage().contains("withLaser"), e.getMessage());
    RobotOptions both = laserAndGripper();
    assertTrue(both.legacyLaserCommands(), "on by default with a laser, as in MobileSim");
    assertTrue(!both.withLaser(false).legacyLaserCommands(), "removing the laser drops it too");
    assertTrue(
        RobotOptions.of("amigo").withLaser(true).legacyLaserCommands(), "adding one adds them");
  }

  @Test
  void rotateTurnsAtTheGivenRateLikeRvel() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.ROTATE, 30);
      w.advanceMillis(2000);
      assertEquals(30, r.getRotVel(), 1e-6, "deg/s, counter-clockwise");
      assertEquals(0, r.getVel(), 1e-9, "no translation");
      double th = r.getTruePose().th();
      assertTrue(th > 20 && th < 60, "turned left: " + th);
      c.comInt(ArCommands.ROTATE, -20);
      w.advanceMillis(2000);
      assertEquals(-20, r.getRotVel(), 1e-6, "negative: clockwise");
      c.comInt(ArCommands.ROTATE, 0);
      w.advanceMillis(2000);
      assertEquals(0, r.getRotVel(), 1e-9);
    }
  }

  @Test
  void getAuxOnAPortWithNothingAttachedIsAnsweredAtOnceWithNoBytes() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot("p3dx-sh");
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.GETAUX2, 5);
      SerAuxPacket aux2 = SerAuxPacket.decode(c.awaitId(PacketIds.SERAUX2));
      assertArrayEquals(new byte[0], aux2.data(), "nothing is attached to AUX2");
      c.comInt(ArCommands.GETAUX3, 200);
      assertEquals(3, SerAuxPacket.decode(c.awaitId(PacketIds.SERAUX3)).port());
      c.clear();
      c.comInt(ArCommands.GETAUX, 10); // AUX1 has the camera, which has said nothing yet
      c.comInt(ArCommands.GETAUX2, 0); // flush: no answer
      w.advanceMillis(300);
      assertTrue(c.packets(PacketIds.SERAUX1).isEmpty(), "waits for the camera's bytes");
      assertTrue(c.packets(PacketIds.SERAUX2).isEmpty());
    }
  }

  @Test
  void commandsNotCarriedOutAreRecordedWithTheReason() {
    try (SimWorld w = SimWorld.empty(OPTS)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withGripper(false).withLaser(false));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.DROTATE, 10);
      c.com2Bytes(ArCommands.PTUPOS, 1, 2);
      c.com(ArCommands.ARM_INFO);
      c.comInt(ArCommands.ARM_GRIPPARK, 5);
      c.comInt(ArCommands.ARM_GRIPPARK, 6);
      c.comInt(ArCommands.SIM_LRF_ENABLE, 1); // no laser on this robot
      c.comInt(ArCommands.SIM_LRF_SET_RES, 50);
      c.comInt(ArCommands.GRIPPER, 1); // no gripper either
      c.comInt(ArCommands.GYRO, 1); // nor a gyro
      c.comInt(200, 1);
      c.comInt(ArCommands.LCDWRITE, 1); // a real command with nothing to simulate: silent
      c.clear();
      w.advanceMillis(300);
      assertEquals(
          List.of(
              new IgnoredCommand(14, "DROTATE", IgnoredCommand.Reason.NOT_SIMULATED, 1),
              new IgnoredCommand(33, "GRIPPER", IgnoredCommand.Reason.NO_DEVICE, 1),
              new IgnoredCommand(41, "PTUPOS", IgnoredCommand.Reason.NOT_SIMULATED, 1),
              new IgnoredCommand(58, "GYRO", IgnoredCommand.Reason.NO_DEVICE, 1),
              new IgnoredCommand(70, "ARM_INFO", IgnoredCommand.Reason.NOT_SIMULATED, 1),
              new IgnoredCommand(81, "ARM_GRIPPARK", IgnoredCommand.Reason.NOT_SIMULATED, 2),
              new IgnoredCommand(200, "unknown", IgnoredCommand.Reason.UNKNOWN, 1),
              new IgnoredCommand(230, "SIM_LRF_ENABLE", IgnoredCommand.Reason.NO_DEVICE, 1),
              new IgnoredCommand(233, "SIM_LRF_SET_RES", IgnoredCommand.Reason.NO_DEVICE, 1)),
          w.getIgnoredCommands());
      assertTrue(c.packets(PacketIds.SIM_LASER).isEmpty(), "no laser, no scans");
      assertTrue(r.isSessionOpen());
      assertEquals(3, c.sips().size(), "the robot carried on");
    }
  }
}
