package org.jaria.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionGoto;
import org.jaria.action.ArActionStallRecover;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.tools.examples.GotoExample;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The thesis's action-based applications on the simulator, on virtual time. */
class ActionScenarioTest {

  /** The five actions of the obstacle-avoidance program (gotoActionExample). */
  private static void addWanderActions(ArRobot robot) {
    robot.addRangeDevice(new ArSonarDevice());
    robot.addAction(new ArActionStallRecover(), 100);
    robot.addAction(new ArActionBumpers(), 75);
    robot.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0), 50);
    robot.addAction(new ArActionAvoidFront(), 49);
    robot.addAction(new ArActionConstantVelocity("Constant Velocity", 400), 25);
    robot.enableMotors();
  }

  /** Wanders for ten minutes; returns {longest stall in ms, half-metre cells visited}. */
  private static long[] wander(SimWorld world) {
    SimRobot r = world.addRobot("p3dx-sh");
    try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
      addWanderActions(sim.robot());
      Set<Long> cells = new HashSet<>();
      long stalledSince = -1;
      long longestStall = 0;
      for (int ms = 0; ms < 600_000; ms += 100) {
        sim.runMillis(100);
        ArPose p = r.getTruePose();
        cells.add(Math.floorDiv((long) p.x(), 500) * 100_003 + Math.floorDiv((long) p.y(), 500));
        if (r.isStalled()) {
          stalledSince = stalledSince < 0 ? ms : stalledSince;
          longestStall = Math.max(longestStall, ms - stalledSince);
        } else {
          stalledSince = -1;
        }
      }
      assertTrue(sim.robot().isConnected());
      return new long[] {longestStall, cells.size()};
    }
  }

  @Test
  void wanderingTheOfficeForTenMinutesRecoversFromEveryStall() {
    try (SimWorld world = SimWorld.bundled("office", SimOptions.builder().seed(21).build())) {
      long[] m = wander(world);
      assertTrue(m[0] <= 3000, "longest stall " + m[0] + " ms");
      assertTrue(m[1] >= 60, "covered only " + m[1] + " half-metre cells");
    }
  }

  @Test
  void wanderingAClutteredHallForTenMinutesRecoversFromEveryStall() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(22).build())) {
      Random rnd = new Random(22);
      for (int i = 0; i < 25; i++) {
        // boxes scattered over the hall, away from the robot's start
        double x = 3000 + rnd.nextDouble() * 14000;
        double y = 1500 + rnd.nextDouble() * 12000;
        world.injectBox(
            x,
            y,
            300 + rnd.nextDouble() * 500,
            300 + rnd.nextDouble() * 500,
            rnd.nextDouble() * 90);
      }
      long[] m = wander(world);
      assertTrue(m[0] <= 3000, "longest stall " + m[0] + " ms");
      assertTrue(m[1] >= 40, "covered only " + m[1] + " half-metre cells");
    }
  }

  @Test
  void turnControlEndsWithinTwoDegreesAndAlwaysTurnsTheShortWay() {
    SimOptions opts = SimOptions.builder().seed(5).build();
    try (SimWorld world = SimWorld.bundled("hall", opts)) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withGyro(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArRobot robot = sim.robot();
        new org.jaria.gyro.ArAnalogGyro(robot);
        robot.enableMotors();
        sim.runMillis(2000); // the gyro learns its bias at rest
        double start = r.getTruePose().th();
        for (double target : new double[] {90, 180, 270, 0}) {
          double before = robot.getTh();
          robot.setHeading(target);
          sim.runMillis(300);
          double shortWay = ArMath.subAngle(target, before);
          assertTrue(
              Math.signum(r.getRotVel()) == Math.signum(shortWay),
              "turning from " + before + " to " + target + " the short way");
          assertTrue(sim.runUntil(robot::isHeadingDone, Duration.ofSeconds(10)));
          sim.runMillis(1500);
          double trueTurn = ArMath.subAngle(r.getTruePose().th(), start);
          assertEquals(
              0, ArMath.subAngle(trueTurn, target), 2.0, "true heading at " + target + "°");
        }
      }
    }
  }

  @Test
  void theGyroKeepsTheHeadingWhenTheWheelsSlip() {
    // A skid-steer P3-AT slips when it turns: its wheels overstate or understate every turn.
    SimOptions opts =
        SimOptions.builder().seed(6).odometryError(OdometryError.constant(0.0, 0.08)).build();
    try (SimWorld world = SimWorld.bundled("hall", opts)) {
      SimRobot r = world.addRobot(RobotOptions.of("p3at-sh").withGyro(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArRobot robot = sim.robot();
        new org.jaria.gyro.ArAnalogGyro(robot);
        robot.enableMotors();
        sim.runMillis(2000);
        double start = r.getTruePose().th();
        double startRaw = robot.getRawEncoderPose().th();
        double startFused = robot.getTh();
        robot.setRotVel(40);
        sim.runMillis(18_000); // two full turns
        robot.setRotVel(0);
        sim.runMillis(1000);
        double trueTurn = ArMath.subAngle(r.getTruePose().th(), start);
        double wheelError =
            Math.abs(
                ArMath.subAngle(
                    ArMath.subAngle(robot.getRawEncoderPose().th(), startRaw), trueTurn));
        double fusedError =
            Math.abs(ArMath.subAngle(ArMath.subAngle(robot.getTh(), startFused), trueTurn));
        assertTrue(
            fusedError < wheelError / 2,
            "gyro-fused error " + fusedError + "° against the wheels' " + wheelError + "°");
      }
    }
  }

  @Test
  void gotoReachesEveryPoseWithinItsCloseDistanceAroundABoxOnTheWay() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(9).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      // A small box in the middle of the first leg: the avoid actions must take the robot round.
      ArPose home = r.getTruePose();
      double t = Math.toRadians(home.th());
      world.injectBox(
          home.x() + 750 * Math.cos(t), home.y() + 750 * Math.sin(t), 250, 250, home.th());
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArRobot robot = sim.robot();
        addWanderActions(robot);
        robot.remAction("Constant Velocity");
        ArActionGoto go = new ArActionGoto("goto", GotoExample.SQUARE.get(0), 100, 400, 150, 7);
        robot.addAction(go, 40);
        int[] stalledSteps = {0};
        double[] widestOnFirstLeg = {0};
        world.addStepListener(
            () -> {
              stalledSteps[0] += r.isStalled() ? 1 : 0;
              if (robot.getX() < 1200) {
                widestOnFirstLeg[0] = Math.max(widestOnFirstLeg[0], Math.abs(robot.getY()));
              }
            });
        for (ArPose goal : GotoExample.SQUARE) {
          go.setGoal(goal);
          if (goal.equals(GotoExample.SQUARE.get(1))) {
            assertTrue(
                widestOnFirstLeg[0] > 200,
                "the first leg swerved round the box (" + widestOnFirstLeg[0] + " mm)");
          }
          assertTrue(sim.runUntil(go::haveAchievedGoal, Duration.ofSeconds(60)), "reached " + goal);
          assertTrue(robot.getPose().findDistanceTo(goal) <= 100, "within 100 mm of " + goal);
        }
        assertEquals(0, stalledSteps[0], "the robot went round the box without touching it");
      }
    }
  }

  @Test
  void bumpersStopAndBackOffFromAnObstacle(@TempDir Path params) throws IOException {
    // Bump rings are an option on a P3-DX: this robot's own parameter file says it has them.
    Files.writeString(
        params.resolve("MobileSim.p"),
        "Section Accessories the robot has\nFrontBumpers true\nRearBumpers true\n");
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(4).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      ArRobot client = new ArRobot("bumpy", world.getClock(), true);
      client.setParamsDirectory(params);
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r, client)) {
        ArRobot robot = sim.robot();
        assertTrue(robot.getRobotParams().haveFrontBumpers());
        robot.addAction(new ArActionBumpers(), 75);
        robot.addAction(new ArActionConstantVelocity("forward", 300), 25);
        robot.enableMotors();
        ArPose p = r.getTruePose();
        double t = Math.toRadians(p.th());
        world.injectBox(p.x() + 1200 * Math.cos(t), p.y() + 1200 * Math.sin(t), 200, 1000, p.th());
        assertTrue(
            sim.runUntil(() -> robot.getFrontBumpers() != 0, Duration.ofSeconds(10)), "bump");
        assertTrue(sim.runUntil(() -> robot.getVel() < -10, Duration.ofSeconds(2)), "backs off");
        assertTrue(sim.runUntil(() -> robot.getFrontBumpers() == 0, Duration.ofSeconds(3)));
        assertFalse(r.isStalled());
      }
    }
  }
}
