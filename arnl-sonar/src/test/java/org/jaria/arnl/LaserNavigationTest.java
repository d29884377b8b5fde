package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The laser navigation scenario: a robot with drifting odometry and a simulated laser localizes
 * with {@link ArLocalizationTask} and drives to goals with {@link ArPathPlanningTask}, on virtual
 * time; the simulator's true pose says whether it really got there.
 */
@Tag("slow")
class LaserNavigationTest {

  @Test
  void aLaserLocalizedRobotReachesTwoGoalsThroughDoors() {
    ArMap office = ArMap.loadBundled("office");
    SimulatedRobot sim = SimSetup.start(office, 6);
    try {
      ArRobot robot = sim.robot();
      // tag::setup[]
      ArSimulatedLaser laser = new ArSimulatedLaser(); // or an ArLMS2xx, ArUrg
      robot.addRangeDevice(laser);
      ArLocalizationTask loc =
          ArLocalizationTask.builder(robot, office)
              .laser(laser)
              .mode(ArLocalizationTask.UpdateMode.SYNCHRONOUS) // lockstep; THREADED on a robot
              .seed(6)
              .build();
      ArPathPlanningTask path =
          ArPathPlanningTask.builder(robot, office).mode(PlanMode.SYNCHRONOUS).build();
      path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
      path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
      // end::setup[]
      sim.runMillis(1000);
      assertTrue(loc.localizeRobotAtHomeBlocking(), "localized at home");
      for (String goal : new String[] {"Lab Entrance", "Corridor West"}) {
        assertTrue(path.pathPlanToGoal(goal), "planned to " + goal);
        assertTrue(sim.runUntil(() -> !path.isActive(), Duration.ofMinutes(3)), "done: " + goal);
        assertEquals(PathPlanningState.REACHED_GOAL, path.getState(), path.getStatusString());
        ArPose target = office.findMapObject(goal).orElseThrow().pose();
        ArPose truth = sim.sim().getTruePose();
        assertTrue(truth.findDistanceTo(target) < 250, goal + ": truly at " + truth);
        assertTrue(
            truth.findDistanceTo(sim.robot().getPose()) < 80,
            "believed " + sim.robot().getPose() + ", truly " + truth);
        assertTrue(loc.getRobotIsLocalized());
      }
      path.close();
      loc.close();
    } finally {
      SimSetup.stop(sim);
    }
  }
}
