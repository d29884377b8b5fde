package org.jaria.arnl;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;

/** A simulated robot localized at home, with sonar localization and path planning on its map. */
record PlanningRig(SimulatedRobot sim, ArSonarLocalizationTask loc, ArPathPlanningTask path) {

  /** Starts one on {@code map} (synchronous localization; planning in {@code mode}). */
  static PlanningRig start(ArMap map, long seed, PlanMode mode) {
    SimulatedRobot sim = SimSetup.start(map, seed);
    ArSonarLocalizationTask loc =
        ArSonarLocalizationTask.builder(sim.robot(), map)
            .mode(ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS)
            .seed(seed)
            .build();
    ArPathPlanningTask path = ArPathPlanningTask.builder(sim.robot(), map).mode(mode).build();
    sim.runMillis(1000);
    assertTrue(loc.localizeRobotAtHomeBlocking(), "localized at home");
    return new PlanningRig(sim, loc, path);
  }

  ArRobot robot() {
    return sim.robot();
  }

  /** Runs until the goal is no longer active; returns whether that happened in time. */
  boolean finish(Duration max) {
    return sim.runUntil(() -> !path.isActive(), max);
  }

  void close() {
    path.close();
    loc.close();
    SimSetup.stop(sim);
  }
}
