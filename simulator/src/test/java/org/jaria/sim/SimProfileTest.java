package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.sim.robot.SimProfile;
import org.junit.jupiter.api.Test;

/**
 * The two profiles against known geometry and motion: MobileSim's ray sonar, drifting odometry and
 * model top speeds, and the real Pioneer's sonar cone and exact odometry.
 */
class SimProfileTest {

  private static final SimOptions MOBILESIM =
      SimOptions.builder().profile(SimProfile.MOBILESIM).watchdogMillis(0).seed(3).build();

  private static final SimOptions PIONEER = SimOptions.builder().watchdogMillis(0).seed(3).build();

  /**
   * A wall piece 25° to 33° left of sonar 3 (whose axis points 10° left): inside the real sonar's
   * 30° cone, away from MobileSim's single ray.
   */
  private static final List<ArLineSegment> OFF_AXIS =
      List.of(new ArLineSegment(1200, 500, 1200, 700));

  private static int lastReading(ArcosTestClient c, int transducer) {
    int range = -1;
    for (StandardSip s : c.sips()) {
      for (int k = 0; k < s.getSonarCount(); k++) {
        if (s.getSonarNumber(k) == transducer) {
          range = s.getSonarRange(k);
        }
      }
    }
    return range;
  }

  @Test
  void mobileSimsSonarIsOneRayAlongTheAxisAndTheRealOnesIsACone() {
    try (SimWorld w = SimWorld.ofLines(OFF_AXIS, ArPose.ORIGIN, MOBILESIM)) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh")).open();
      w.advanceMillis(1000);
      assertEquals(5000, lastReading(c, 3), "the ray passes beside the wall piece");
    }
    try (SimWorld w = SimWorld.ofLines(OFF_AXIS, ArPose.ORIGIN, PIONEER)) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx-sh")).open();
      w.advanceMillis(1000);
      // the cone's edge ray (25°) meets the wall 1034 / cos 25° from the transducer
      assertEquals(1141, lastReading(c, 3), 60, "the cone's edge finds it");
    }
  }

  @Test
  void mobileSimsSonarReadsAnEchoNearerThanItsMinimumAsTheMinimum() {
    // a wall 60 mm in front of sonar 3 and 4
    List<ArLineSegment> close = List.of(new ArLineSegment(230, -300, 230, 300));
    try (SimWorld w = SimWorld.ofLines(close, ArPose.ORIGIN, MOBILESIM)) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      w.advanceMillis(500);
      assertEquals(100, lastReading(c, 3));
    }
  }

  @Test
  void mobileSimsOdometryDriftsWithinItsBoundAndThePioneersIsExact() {
    double[] errors = new double[2];
    int k = 0;
    for (SimOptions o : List.of(MOBILESIM, PIONEER)) {
      try (SimWorld w = SimWorld.empty(o)) {
        SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
        ArcosTestClient c = new ArcosTestClient(w, r).open();
        c.comInt(ArCommands.VEL, 400);
        c.comInt(ArCommands.RVEL, 20);
        w.advanceMillis(8000);
        double truePath = r.getDistanceDriven();
        ArPose odo = r.getOdometryPose();
        ArPose truth = r.getTruePose();
        double odoTurn = odo.th();
        double trueTurn = truth.th();
        errors[k++] =
            Math.abs(odoTurn - trueTurn) + Math.hypot(odo.x() - truth.x(), odo.y() - truth.y());
        assertTrue(truePath > 2500, "it drove: " + truePath);
        // each 100 ms the scale errs by at most 0.75 % of that stretch
        assertTrue(
            Math.hypot(odo.x() - truth.x(), odo.y() - truth.y()) <= 0.0075 * truePath + 1,
            o.profile() + ": " + odo + " vs " + truth);
      }
    }
    assertTrue(errors[0] > 0.01, "MobileSim's odometry drifts: " + errors[0]);
    assertEquals(0, errors[1], 1e-6, "a real Pioneer's simulated odometry is exact by default");
  }

  @Test
  void mobileSimTurnsToAHeadingInProportionToWhatIsLeftAndARealPioneerAtOnce() {
    double[] after = new double[2];
    int k = 0;
    for (SimOptions o : List.of(MOBILESIM, PIONEER)) {
      try (SimWorld w = SimWorld.empty(o)) {
        SimRobot r = w.addRobot(RobotOptions.of("p3dx").withStartPose(ArPose.ORIGIN));
        ArcosTestClient c = new ArcosTestClient(w, r).open();
        c.comInt(ArCommands.HEAD, 10);
        w.advanceMillis(1000);
        after[k++] = r.getTruePose().th();
      }
    }
    // MobileSim: the turn rate is the error (rad) per second, so 10° take seconds to close
    assertTrue(after[0] > 3 && after[0] < 8, "MobileSim's HEAD after 1 s: " + after[0]);
    assertEquals(10, after[1], 0.5, "a real Pioneer's HEAD after 1 s");
  }

  @Test
  void mobileSimsRobotGoesNoFasterThanItsModelsTopSpeed() {
    try (SimWorld w = SimWorld.empty(MOBILESIM)) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx")).open();
      c.comInt(ArCommands.VEL, 2000);
      w.advanceMillis(8000);
      assertEquals(1000, w.getRobots().get(0).getVel(), 1, "MobileSim's p3dx: 1 m/s");
    }
    try (SimWorld w = SimWorld.empty(PIONEER)) {
      ArcosTestClient c = new ArcosTestClient(w, w.addRobot("p3dx")).open();
      c.comInt(ArCommands.VEL, 2000);
      w.advanceMillis(8000);
      assertEquals(1500, w.getRobots().get(0).getVel(), 1, "TransVelMax of the FLASH");
    }
  }

  /** The first whole scan the client received, mm per beam. */
  private static int[] firstScan(ArcosTestClient c) {
    int[] out = null;
    for (ArRobotPacket p : c.packets(PacketIds.SIM_LASER_EXTENDED)) {
      p.resetRead();
      int total = p.bufToUByte2();
      int first = p.bufToUByte2();
      int n = p.bufToUByte();
      if (out == null) {
        out = new int[total];
      }
      for (int k = 0; k < n; k++) {
        out[first + k] = p.bufToUByte2();
        p.skip(3);
      }
      if (first + n >= total) {
        return out;
      }
    }
    throw new AssertionError("no whole scan");
  }

  @Test
  void mobileSimsLaserBeamsAre180Over181DegreesApart() {
    // a wall across the robot's path, 1 m ahead of the laser (a p3dx's is at its centre)
    List<ArLineSegment> wall = List.of(new ArLineSegment(1000, -5000, 1000, 5000));
    int[][] scans = new int[2][];
    int k = 0;
    for (SimOptions o : List.of(MOBILESIM, PIONEER)) {
      try (SimWorld w = SimWorld.ofLines(wall, ArPose.ORIGIN, o)) {
        SimRobot r = w.addRobot(RobotOptions.of("p3dx").withStartPose(ArPose.ORIGIN));
        ArcosTestClient c = new ArcosTestClient(w, r).open();
        c.comInt(ArCommands.SIM_LRF_ENABLE, 2);
        w.advanceMillis(300);
        scans[k++] = firstScan(c);
      }
    }
    assertEquals(181, scans[0].length);
    // reading 150, which ARIA places at 60°: MobileSim's beam points at 150 × 180/181 − 90°
    double mobileSim = 1000 / Math.cos(Math.toRadians(150 * 180.0 / 181 - 90));
    assertEquals(mobileSim, scans[0][150], 25, "MobileSim's beam spacing");
    assertEquals(2000, scans[1][150], 25, "a real laser's 1° spacing");
    assertEquals(1000, scans[0][90], 25, "straight ahead both ways");
  }

  @Test
  void mobileSimLeavesTheRequestsItNeverAnsweredUnanswered() {
    int[] requests = {
      ArCommands.ENCODER.getNumber(),
      ArCommands.IOREQUEST.getNumber(),
      ArCommands.JOYREQUEST.getNumber(),
      ArCommands.TCM2.getNumber()
    };
    int[] answers = {PacketIds.ENCODER, PacketIds.IO, PacketIds.JOYSTICK, PacketIds.TCM2};
    for (SimOptions o : List.of(MOBILESIM, PIONEER)) {
      try (SimWorld w = SimWorld.empty(o)) {
        SimRobot r = w.addRobot(RobotOptions.of("p3dx").withLaser(false));
        ArcosTestClient c = new ArcosTestClient(w, r).open();
        for (int q : requests) {
          c.comInt(q, q == ArCommands.TCM2.getNumber() ? 3 : 2);
        }
        c.comInt(ArCommands.GRIPREQUEST, 2);
        w.advanceMillis(500);
        for (int a : answers) {
          assertEquals(
              o.profile() == SimProfile.PIONEER,
              !c.packets(a).isEmpty(),
              o.profile() + ": packet 0x" + Integer.toHexString(a));
        }
        assertEquals(o.profile() == SimProfile.PIONEER, !c.packets(PacketIds.GRIPPER).isEmpty());
      }
    }
  }

  @Test
  void profilesHaveCommandLineNamesAndTheirOwnDefaults() {
    assertEquals(SimProfile.MOBILESIM, SimProfile.parse(" MobileSim "));
    assertEquals(SimProfile.PIONEER, SimProfile.parse("pioneer"));
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> SimProfile.parse("stage"));
    assertTrue(e.getMessage().contains("mobilesim") && e.getMessage().contains("pioneer"));
    assertEquals(SimProfile.PIONEER, SimOptions.defaults().profile());
    assertEquals(OdometryError.NONE, SimOptions.defaults().odometryError());
    assertEquals(SimProfile.MOBILESIM_ODOMETRY, MOBILESIM.odometryError());
    assertNotEquals(MOBILESIM.sonar(), PIONEER.sonar());
    try (SimWorld w = SimWorld.empty(MOBILESIM)) {
      assertEquals(null, w.addRobot("p3dx").body().gripper(), "MobileSim simulates no gripper");
    }
  }
}
