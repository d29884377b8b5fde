package org.jaria.web.source;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.arnl.ArBaseLocalizationTask;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.WorldFrame;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The sources on a simulated robot in lockstep (virtual time): the world's truth, the robot's
 * localization and path laid over it, and the viewers' driver moving it.
 */
@Tag("slow")
class RobotViewSourcesTest {

  static final ArMap OFFICE = ArMap.loadBundled("office");

  SimWorld world;
  SimulatedRobot sim;
  ArRobot robot;
  ArSonarLocalizationTask loc;
  ArPathPlanningTask path;
  RobotDriver driver;
  SimWorldSource source;

  @BeforeEach
  void start() {
    world = SimWorld.create(OFFICE, SimOptions.builder().seed(1).build());
    SimRobot r = world.addRobot("p3dx-sh");
    sim = SimulatedRobot.connect(world, r);
    robot = sim.robot();
    robot.addRangeDevice(new ArSimulatedLaser());
    loc =
        ArSonarLocalizationTask.builder(robot, OFFICE)
            .mode(ArBaseLocalizationTask.UpdateMode.SYNCHRONOUS)
            .seed(1)
            .build();
    path =
        ArPathPlanningTask.builder(robot, OFFICE)
            .mode(ArPathPlanningTask.PlanMode.SYNCHRONOUS)
            .build();
    path.getPathPlanActionGroup().deactivate(); // as a server's stop mode leaves it
    robot.enableMotors();
    sim.runMillis(1000);
    assertTrue(loc.localizeRobotAtHomeBlocking(), "localized at home");
    driver = new RobotDriver(robot, path);
    source = new SimWorldSource(world, new SimulationControl(world, 1), OFFICE, "office");
    source.addOverlay(
        r.getName(), new NavigationSource(robot, OFFICE, "office", loc, path, driver));
  }

  @AfterEach
  void stop() {
    driver.close();
    sim.close();
    world.close();
  }

  RobotFrame frame() {
    WorldFrame f = source.frame();
    assertEquals(1, f.robots().size());
    return f.robots().get(0);
  }

  @Test
  void aFrameHasTheTruthAndWhatTheRobotBelieves() {
    sim.runMillis(500);
    RobotFrame r = frame();
    assertEquals(sim.sim().getTruePose(), r.truePose());
    assertNotNull(r.believedPose());
    assertTrue(r.believedPose().findDistanceTo(r.truePose()) < 200, r.toString());
    assertTrue(r.particles().size() > 100, "particles: " + r.particles().size());
    assertTrue(r.sonarEchoes().size() > 0 && r.sonarEchoes().size() <= 16);
    assertNotNull(r.laser(), "the laser scans");
    assertEquals(181, r.laser().size());
    assertEquals(4, r.footprint().size());
    assertEquals("ready", r.status().mode());
    assertTrue(r.status().localizationScore() > 0.5, r.status().toString());
    assertTrue(source.frame().clock().simulated());
    MapLayer map = source.map();
    assertTrue(map.goals().stream().anyMatch(g -> g.name().equals("Corridor West")));
    assertEquals(1, map.forbiddenAreas().size());
    assertTrue(map.lineCount() > 20);
    assertEquals(map, source.map());
  }

  @Test
  void aDriveHoldsForAMomentThenTheRobotStopsByItself() {
    ArPose start = sim.sim().getTruePose();
    driver.drive(300, 0);
    sim.runMillis(400);
    assertTrue(driver.isDriving());
    assertEquals("teleop", frame().status().mode());
    for (int i = 0; i < 4; i++) {
      driver.drive(300, 0); // renewed within the hold: keeps going
      sim.runMillis(400);
    }
    double moved = sim.sim().getTruePose().findDistanceTo(start);
    assertTrue(moved > 200, "drove: " + moved);
    sim.runMillis(2000); // no renewal: the hold runs out
    assertFalse(driver.isDriving());
    assertEquals(0, sim.sim().getVel(), 1);
    double stoppedAt = sim.sim().getTruePose().findDistanceTo(start);
    sim.runMillis(1000);
    assertEquals(stoppedAt, sim.sim().getTruePose().findDistanceTo(start), 1);
  }

  @Test
  void aGoalAfterDrivingIsReachedAlongAPlannedPath() {
    driver.drive(300, 0);
    sim.runMillis(1500);
    ArPose goal = new ArPose(5000, 9500);
    assertTrue(driver.goTo(goal, false));
    sim.runMillis(500);
    RobotFrame r = frame();
    assertTrue(r.path().size() >= 2, "a path is shown: " + r.path());
    assertEquals(goal.x(), r.goal().x(), 1);
    assertTrue(
        sim.runUntil(
            () -> path.getState() == ArPathPlanningTask.PathPlanningState.REACHED_GOAL,
            Duration.ofMinutes(2)),
        "reached: " + path.getState() + " " + path.getFailureString());
    assertTrue(
        sim.sim().getTruePose().findDistanceTo(goal) < 400, sim.sim().getTruePose().toString());
    assertEquals("goal reached", frame().status().mode());
    assertNull(frame().goal(), "no goal once it is reached");
  }
}
