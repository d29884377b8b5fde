package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;
import org.junit.jupiter.api.Test;

/** Odometry error modes, the SIP position encoding, and run-to-run determinism. */
class OdometryAndDeterminismTest {

  /** Drives a fixed script: straight, turn, straight; returns the client. */
  private static ArcosTestClient drive(SimWorld w, SimRobot r) {
    ArcosTestClient c = new ArcosTestClient(w, r).autoPulse(500).open();
    c.comInt(ArCommands.VEL, 500);
    w.advanceMillis(4000);
    c.comInt(ArCommands.VEL, 0);
    c.comInt(ArCommands.RVEL, 45);
    w.advanceMillis(3000);
    c.comInt(ArCommands.RVEL, 0);
    c.comInt(ArCommands.VEL, 400);
    w.advanceMillis(3000);
    c.comInt(ArCommands.VEL, 0);
    w.advanceMillis(3000);
    return c;
  }

  private static SimOptions opts(OdometryError e, long seed) {
    return SimOptions.builder().odometryError(e).seed(seed).watchdogMillis(0).build();
  }

  @Test
  void exactOdometryFollowsTheTruePose() {
    try (SimWorld w = SimWorld.empty(opts(OdometryError.NONE, 1))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = drive(w, r);
      ArPose t = r.getTruePose();
      ArPose o = r.getOdometryPose();
      assertEquals(t.x(), o.x(), 1e-6);
      assertEquals(t.y(), o.y(), 1e-6);
      assertEquals(t.th(), o.th(), 1e-9);
      // The SIP carries the odometry pose in robot units (DistConvFactor, AngleConvFactor).
      StandardSip s = c.lastSip();
      double dist = r.getModel().getDistConvFactor();
      assertEquals(Math.round(o.x() / dist) & 0x7FFF, s.getXPos());
      assertEquals(Math.round(o.y() / dist) & 0x7FFF, s.getYPos());
      assertEquals(
          Math.round(Math.toRadians(o.th()) / r.getModel().getAngleConvFactor()), s.getThPos());
    }
  }

  @Test
  void constantErrorScalesDistanceAndRotation() {
    OdometryError e = OdometryError.constant(0.05, -0.1);
    try (SimWorld w = SimWorld.empty(opts(e, 1))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(3000);
      c.comInt(ArCommands.VEL, 0);
      w.advanceMillis(3000);
      double trueDist = r.getTruePose().x();
      assertEquals(1.05 * trueDist, r.getOdometryPose().x(), 1e-6);
      c.comInt(ArCommands.RVEL, 30);
      w.advanceMillis(2000);
      c.comInt(ArCommands.RVEL, 0);
      w.advanceMillis(2000);
      double trueTurn = r.getTruePose().th();
      assertEquals(0.9 * trueTurn, r.getOdometryPose().th(), 1e-6);
    }
  }

  @Test
  void moveCountsEncoderDistanceSoErrorChangesTheTrueDistance() {
    OdometryError e = OdometryError.constant(0.1, 0);
    try (SimWorld w = SimWorld.empty(opts(e, 1))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.MOVE, 1100);
      w.advanceMillis(8000);
      assertEquals(1100, r.getOdometryPose().x(), 0.5);
      assertEquals(1000, r.getTruePose().x(), 0.5);
    }
  }

  @Test
  void randomErrorIsSeededAndGrowsWithDistance() {
    OdometryError e = OdometryError.random(0.05, 0.05);
    ArPose[] odo = new ArPose[3];
    ArPose[] truth = new ArPose[3];
    long[] seeds = {5, 5, 6};
    for (int k = 0; k < 3; k++) {
      try (SimWorld w = SimWorld.empty(opts(e, seeds[k]))) {
        SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
        drive(w, r);
        odo[k] = r.getOdometryPose();
        truth[k] = r.getTruePose();
      }
    }
    assertEquals(truth[0], truth[1]);
    assertEquals(truth[0], truth[2], "the true motion does not depend on the error");
    assertEquals(odo[0], odo[1], "same seed, same odometry");
    assertFalse(odo[0].equals(odo[2]), "another seed, another odometry");
    double err = odo[0].findDistanceTo(truth[0]);
    assertTrue(err > 0.1, "odometry erred by " + err);
    assertTrue(err < 1000, "but plausibly: " + err);
    assertTrue(Math.abs(ArMath.subAngle(odo[0].th(), truth[0].th())) < 30);
  }

  @Test
  void ticksMmRevCountAndDriftFactorBendOdometryLikeOnTheRobot() {
    try (SimWorld w = SimWorld.empty(opts(OdometryError.NONE, 1))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(ArPose.ORIGIN));
      ArcosTestClient c = new ArcosTestClient(w, r).open();
      c.comInt(ArCommands.CONFIG, 1);
      ArConfigPacket cfg = ArConfigPacket.decode(c.awaitId(PacketIds.CONFIG));
      int ticks = cfg.getTicksMM();
      int rev = cfg.getInt(ArConfigPacket.Field.REV_COUNT);
      assertTrue(ticks > 0 && rev > 0);

      c.comInt(ArCommands.TICKSMM, 2 * ticks); // doubled: every distance reads half
      c.comInt(ArCommands.VEL, 500);
      w.advanceMillis(3000);
      c.comInt(ArCommands.VEL, 0);
      w.advanceMillis(3000);
      assertEquals(r.getTruePose().x() / 2, r.getOdometryPose().x(), 1e-6);

      c.comInt(ArCommands.TICKSMM, ticks);
      int half = rev / 2;
      c.comInt(ArCommands.REVCOUNT, half); // halved: every turn reads (about) double
      c.com(ArCommands.SETO);
      c.comInt(ArCommands.RVEL, 30);
      w.advanceMillis(2000);
      c.comInt(ArCommands.RVEL, 0);
      w.advanceMillis(2000);
      double turned = r.getTruePose().th();
      assertTrue(Math.abs(turned) > 30 && Math.abs(turned) < 90, "turned " + turned);
      assertEquals(turned * rev / (double) half, r.getOdometryPose().th(), 0.05);

      c.comInt(ArCommands.REVCOUNT, rev);
      c.comInt(
          ArCommands.DRIFTFACTOR, 819); // +10 %: the left wheel reads long, odometry veers right
      c.com(ArCommands.SETO);
      double th0 = r.getTruePose().th();
      c.comInt(ArCommands.VEL, 400);
      w.advanceMillis(3000);
      assertEquals(th0, r.getTruePose().th(), 1e-9, "the robot really drives straight");
      assertTrue(r.getOdometryPose().th() < -1, "odometry " + r.getOdometryPose());
      c.comInt(ArCommands.CONFIG, 1);
      c.clear();
      cfg = ArConfigPacket.decode(c.awaitId(PacketIds.CONFIG));
      assertEquals(819, cfg.getInt(ArConfigPacket.Field.DRIFT_FACTOR));
    }
  }

  @Test
  void odometryErrorParsesTheCommandLineForm() {
    assertEquals(OdometryError.NONE, OdometryError.parse("none"));
    assertEquals(OdometryError.random(0.02, 0.05), OdometryError.parse("random:0.02,0.05"));
    assertEquals(OdometryError.constant(-0.01, 0.1), OdometryError.parse(" Constant:-0.01, 0.1"));
    IllegalArgumentException ex =
        assertThrows(IllegalArgumentException.class, () -> OdometryError.parse("random:0.02"));
    assertTrue(ex.getMessage().contains("random:T,R"));
    assertThrows(IllegalArgumentException.class, () -> OdometryError.parse("gauss:1,2"));
    assertThrows(IllegalArgumentException.class, () -> OdometryError.parse("random:-1,2"));
  }

  /** Two runs with the same seed and the same commands give byte-identical SIP streams. */
  @Test
  void sameSeedGivesIdenticalByteStreams() {
    byte[][] runs = new byte[3][];
    long[] seeds = {11, 11, 12};
    for (int k = 0; k < 3; k++) {
      SimOptions o = opts(OdometryError.random(0.03, 0.03), seeds[k]);
      try (SimWorld w = SimWorld.bundled("office", o)) {
        SimRobot r = w.addRobot(RobotOptions.of("p3at-sh").withGyro(true).withLaser(true));
        w.addRobot("p3dx-sh");
        ArcosTestClient c = new ArcosTestClient(w, r).autoPulse(500).open();
        c.comInt(ArCommands.GYRO, 1);
        c.comInt(ArCommands.SIM_LRF_ENABLE, 1);
        c.comInt(ArCommands.SIM_STAT, 2);
        c.comInt(ArCommands.ENCODER, 2);
        for (int leg = 0; leg < 6; leg++) {
          c.comInt(ArCommands.VEL, 300 + 50 * leg);
          c.comInt(ArCommands.RVEL, leg % 2 == 0 ? 20 : -25);
          w.advanceMillis(5000);
        }
        runs[k] = c.rawIn.toByteArray();
      }
    }
    assertTrue(runs[0].length > 100_000, "a substantial stream: " + runs[0].length);
    assertArrayEquals(runs[0], runs[1]);
    assertFalse(Arrays.equals(runs[0], runs[2]), "another seed gives other noise");
  }

  @Test
  void theHeadingCounterWrapsAt4096UnitsSoARobotUnwrapsTurnsExactly() {
    // A turn is 4107 units of the parameter file's AngleConvFactor (0.00153), but ARCOS's THPOS
    // wraps at 4096 and ARIA unwraps it so: a counter taken from the wrapped heading jumped by
    // 4107 units at each crossing of ±180°, and the robot's heading lost 0.94° there.
    try (SimWorld w = SimWorld.empty(opts(OdometryError.NONE, 1))) {
      SimRobot r = w.addRobot(RobotOptions.of("p3dx-sh").withStartPose(new ArPose(0, 0, 150)));
      ArcosTestClient c = new ArcosTestClient(w, r).autoPulse(500).open();
      double conv = r.getModel().getAngleConvFactor();
      c.comInt(ArCommands.RVEL, 60);
      int last = c.lastSip().getThPos();
      double lastTrue = r.getTruePose().th();
      double unwrapped = 0;
      double turned = 0;
      for (int step = 0; step < 140; step++) {
        if (step == 130) {
          // Stop, so that the last SIP and the true pose describe the same heading.
          c.comInt(ArCommands.RVEL, 0);
        }
        w.advanceMillis(100);
        int th = c.lastSip().getThPos();
        // As ARIA: the difference of two THPOS values, taken modulo 4096 units.
        unwrapped += Math.toDegrees(conv * (Math.floorMod(th - last + 2048, 4096) - 2048));
        last = th;
        turned += ArMath.subAngle(r.getTruePose().th(), lastTrue);
        lastTrue = r.getTruePose().th();
      }
      assertTrue(turned > 720, "turned " + turned + " degrees, crossing +-180 at least twice");
      assertEquals(turned, unwrapped, 0.1, "the robot's unwrapped heading follows the turns");
    }
  }
}
