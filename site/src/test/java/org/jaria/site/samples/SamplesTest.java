package org.jaria.site.samples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.client.SimulatedRobot.ProgramResult;
import org.junit.jupiter.api.Test;

/** Every sample the guides quote does what the guide says it does, on the simulator. */
class SamplesTest {

  @Test
  void helloRobotDrivesASquareAndEndsWhereItStarted() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 1)) {
      ArPose start = sim.sim().getTruePose();
      boolean[] drove = new boolean[1];
      ProgramResult r =
          sim.runProgram(
              robot -> {
                try {
                  drove[0] = HelloRobot.square(robot, 1000);
                } catch (InterruptedException e) {
                  Thread.currentThread().interrupt();
                }
              },
              Duration.ofMinutes(1));
      assertEquals(ProgramResult.FINISHED, r);
      assertTrue(drove[0], "square() says it drove the whole square");
      double off = sim.sim().getTruePose().findDistanceTo(start);
      assertTrue(off < 150, "back within 150 mm of the start: " + off);
    }
  }

  /**
   * On the office map the robot starts in a corridor and the square's second side runs into a wall:
   * the program notices the stall and gives up instead of waiting for ever.
   */
  @Test
  void helloRobotGivesUpWhenAWallIsInTheWay() {
    try (SimulatedRobot sim = SimulatedRobot.start("office", "p3dx-sh", 1)) {
      boolean[] drove = {true};
      ProgramResult r =
          sim.runProgram(
              robot -> {
                try {
                  drove[0] = HelloRobot.square(robot, 1000);
                } catch (InterruptedException e) {
                  Thread.currentThread().interrupt();
                }
              },
              Duration.ofMinutes(2));
      assertEquals(ProgramResult.FINISHED, r, "the program ended by itself");
      assertFalse(drove[0], "square() reports that it gave up");
      assertEquals(0, sim.robot().getVel(), 5, "and left the robot stopped");
    }
  }

  @Test
  void theCycleTasksRunEveryCycleAndTheUserTaskReportsOnceASecond() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 1)) {
      ByteArrayOutputStream bytes = new ByteArrayOutputStream();
      CycleSample sample =
          new CycleSample(sim.robot(), new PrintStream(bytes, true, StandardCharsets.UTF_8));
      sim.runMillis(3000);
      String out = bytes.toString(StandardCharsets.UTF_8);
      long lines = out.lines().filter(l -> l.contains("closest ahead")).count();
      assertTrue(lines >= 2 && lines <= 4, "about one line a second:\n" + out);
      assertTrue(sample.closestAhead() > 0, "the sensor task read the sonar");
    }
  }

  @Test
  void theActionsCruiseThenSlowAndStopShortOfAnObstacle() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(2).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      ArPose p = r.getTruePose();
      world.injectBox(p.x() + 4000, p.y(), 300, 1500, 0);
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArRobot robot = sim.robot();
        ActionsSample.addActions(robot);
        sim.runMillis(2000);
        assertTrue(robot.getVel() > 300, "cruising at " + robot.getVel());
        sim.runMillis(20_000);
        double gap = p.x() + 4000 - 150 - r.getTruePose().x();
        assertFalse(r.isStalled(), "never pushed the box");
        assertTrue(gap > 150 && gap < 1200, "stopped short of the box: " + gap + " mm");
      }
    }
  }

  @Test
  void theMapSampleListsTheGoals() throws IOException, MapFormatException {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    ArMap map = MapSample.describe("hall", new PrintStream(bytes, true, StandardCharsets.UTF_8));
    String out = bytes.toString(StandardCharsets.UTF_8);
    assertTrue(out.contains("goal 'Between Pillars'"), out);
    assertEquals(7, map.getGoals().size());
  }

  @Test
  void theNavigationSetUpLocalizesAndReachesAGoal() {
    ArMap map = ArMap.loadBundled("office");
    SimOptions o =
        SimOptions.builder().seed(4).odometryError(OdometryError.random(0.02, 0.02)).build();
    try (SimWorld world = SimWorld.create(map, o)) {
      SimRobot r = world.addRobot("p3dx-sh");
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        NavigationSample.Navigation nav = NavigationSample.setUp(sim.robot(), map, true);
        sim.robot().enableMotors();
        sim.runMillis(1500);
        assertTrue(nav.loc().localizeRobotAtHomeBlocking(), "localized at home");
        assertTrue(nav.path().pathPlanToGoal("Corridor West"));
        assertTrue(sim.runUntil(() -> !nav.path().isActive(), Duration.ofMinutes(2)));
        assertEquals(PathPlanningState.REACHED_GOAL, nav.path().getState());
        ArPose goal = map.findMapObject("Corridor West").orElseThrow().pose();
        assertTrue(r.getTruePose().findDistanceTo(goal) < 400, "at the goal: " + r.getTruePose());
        nav.path().close();
        nav.loc().close();
      }
    }
  }

  @Test
  void theProtocolSampleBuildsTheGoldenEnableBytesAndSeesEncoderPackets() {
    assertEquals("FA FB 06 04 3B 01 00 05 3B", ProtocolSample.enableMotors());
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 1)) {
      java.util.concurrent.atomic.AtomicLong left = ProtocolSample.watchEncoders(sim.robot());
      sim.runMillis(500);
      long before = left.get();
      sim.robot().enableMotors();
      sim.robot().move(500);
      sim.runMillis(4000);
      assertTrue(left.get() > before, "encoder counts " + before + " -> " + left.get());
    }
  }

  @Test
  void theRangeQueriesSeeABoxAhead() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      ArPose p = r.getTruePose();
      world.injectBox(p.x() + 1500, p.y(), 200, 800, 0);
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        RangeSample.addDevices(sim.robot());
        sim.runMillis(2000);
        RangeSample.Around a = RangeSample.look(sim.robot());
        assertEquals(1400, a.ahead(), 150, "the box's face is 1.4 m ahead: " + a);
        assertTrue(a.inBox() >= 5000, "nothing within a metre (the sonar's range or more): " + a);
        assertTrue(a.sonar3() > 1000 && a.sonar3() < 2000, "sonar 3 sees the box: " + a);
      }
    }
  }

  @Test
  void theMappingSampleLogsWhileDrivingAndBuildsTheLog(
      @org.junit.jupiter.api.io.TempDir java.nio.file.Path tmp) throws Exception {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(4).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        org.jaria.range.ArSimulatedLaser laser = new org.jaria.range.ArSimulatedLaser();
        sim.robot().addRangeDevice(laser);
        sim.robot().enableMotors();
        sim.runMillis(1000);
        java.nio.file.Path log = tmp.resolve("hall.2d");
        int scans =
            MappingSample.logWhileDriving(
                sim.robot(),
                laser,
                log,
                () -> {
                  sim.robot().setVel(400);
                  sim.runMillis(8000);
                  sim.robot().setVel(0);
                  sim.robot().setRotVel(30);
                  sim.runMillis(6000);
                  sim.robot().setRotVel(0);
                  sim.runMillis(500);
                });
        assertTrue(scans >= 15, "scans logged: " + scans);
        org.jaria.mapping.BuiltMap m = MappingSample.build(log, tmp.resolve("hall.map"));
        assertTrue(m.pointCount() > 500, "map points: " + m.pointCount());
        assertTrue(java.nio.file.Files.size(tmp.resolve("hall.map")) > 5000);
      }
    }
  }
}
