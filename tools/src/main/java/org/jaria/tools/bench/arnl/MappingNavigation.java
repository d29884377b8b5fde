package org.jaria.tools.bench.arnl;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.ArBaseLocalizationTask;
import org.jaria.arnl.ArLocalizationTask;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.sim.client.SimulatedRobot;

/**
 * Localization and navigation on a built map: the simulated robot lives in the true world, but
 * localizes (laser, {@link ArLocalizationTask}) and plans ({@link ArPathPlanningTask}) on the map
 * built from its log. It starts at home (the built map's RobotHome, the log's first pose) and is
 * sent to random places the logging drive passed (so they are on the map), given in the built map's
 * frame. A goal is only asked for if the route the built map gives to it stays near the logging
 * drive ({@link #EXPLORED_MM}): a built map knows nothing of the places the laser never came near,
 * so its planner takes them for free space, and a route through them (a shortcut through a corridor
 * the drive only glimpsed) leaves the robot among walls its map does not have.
 */
final class MappingNavigation {

  /** Every point of a goal's route on the built map lies this close to a logged pose, mm. */
  static final double EXPLORED_MM = 1500;

  private MappingNavigation() {}

  /**
   * Goals reached, the mean distance from the true pose to the goal at arrival (mm), and each
   * goal's outcome: the distance at arrival in mm, or "missed" and why.
   */
  record Result(
      int goals, int reached, double meanErrorMm, List<String> failures, List<String> perGoal) {}

  static Result run(
      ArMap truth, ArMap built, ArPose builtToTruth, List<ArPose> visited, int goals, long seed) {
    NavigationMap nav = NavigationMap.build(truth, 100, 300, 1000, 4);
    NavigationMap onBuilt = NavigationMap.build(built, 100, 300, 1000, 4);
    ArPose home = truth.findHomePose().orElse(ArPose.ORIGIN);
    ArPose truthToBuilt = TruthCompare.inverse(builtToTruth);
    SplittableRandom rng = new SplittableRandom(seed);
    SimulatedRobot sim = LocalizationBench.world(truth, seed, home);
    int reached = 0;
    List<Double> errors = new ArrayList<>();
    List<String> failures = new ArrayList<>();
    List<String> perGoal = new ArrayList<>();
    try {
      ArSimulatedLaser laser = new ArSimulatedLaser();
      sim.robot().addRangeDevice(laser);
      ArLocalizationTask loc =
          ArLocalizationTask.builder(sim.robot(), built)
              .laser(laser)
              .mode(ArBaseLocalizationTask.UpdateMode.SYNCHRONOUS)
              .seed(seed)
              .build();
      ArPathPlanningTask path =
          ArPathPlanningTask.builder(sim.robot(), built)
              .mode(ArPathPlanningTask.PlanMode.SYNCHRONOUS)
              .build();
      sim.runMillis(1000);
      loc.localizeRobotAtHomeBlocking();
      ArPose at = home;
      for (int g = 0; g < goals; g++) {
        ArPose goal = null;
        for (int tries = 0; tries < 500 && goal == null; tries++) {
          ArPose p = visited.get(rng.nextInt(visited.size()));
          if (p.findDistanceTo(at) > 4000
              && BenchSupport.route(nav, at, p) != null
              && explored(onBuilt, builtToTruth, at, p, visited)) {
            goal = p;
          }
        }
        if (goal == null) {
          break;
        }
        ArPose inBuilt = TruthCompare.compose(truthToBuilt, goal);
        path.pathPlanToPose(inBuilt, false);
        sim.runUntil(() -> !path.isActive(), Duration.ofMinutes(4));
        double err = sim.sim().getTruePose().findDistanceTo(goal);
        if (path.getState() == PathPlanningState.REACHED_GOAL) {
          reached++;
          errors.add(err);
          perGoal.add(String.valueOf(Math.round(err)));
        } else {
          failures.add(goal + ": " + path.getStatusString());
          perGoal.add("missed");
        }
        at = sim.sim().getTruePose();
      }
      path.close();
      loc.close();
    } finally {
      LocalizationBench.close(sim);
    }
    return new Result(goals, reached, BenchSupport.mean(errors), failures, perGoal);
  }

  /**
   * Whether the built map's route from {@code from} to {@code to} (true poses) stays within {@link
   * #EXPLORED_MM} of the logging drive's poses {@code visited}.
   */
  static boolean explored(
      NavigationMap onBuilt, ArPose builtToTruth, ArPose from, ArPose to, List<ArPose> visited) {
    ArPose truthToBuilt = TruthCompare.inverse(builtToTruth);
    List<ArPose> route =
        BenchSupport.route(
            onBuilt,
            TruthCompare.compose(truthToBuilt, from),
            TruthCompare.compose(truthToBuilt, to));
    if (route == null) {
      return false;
    }
    for (ArPose b : route) {
      ArPose t = TruthCompare.compose(builtToTruth, b);
      boolean near = false;
      for (int k = 0; k < visited.size() && !near; k++) {
        near = visited.get(k).findDistanceTo(t) <= EXPLORED_MM;
      }
      if (!near) {
        return false;
      }
    }
    return true;
  }
}
