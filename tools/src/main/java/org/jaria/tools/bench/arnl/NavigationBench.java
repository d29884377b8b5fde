package org.jaria.tools.bench.arnl;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.client.SimulatedRobot;

/**
 * Navigation success: random start and goal pairs in the office map (both clear of walls by half a
 * metre, at least 5 m apart, connected), sonar localization from the start pose and path following
 * with odometry error on.
 */
final class NavigationBench {

  private NavigationBench() {}

  /** Results. */
  record Result(
      int pairs, int reached, double meanSeconds, double meanFinalError, List<String> failures) {}

  static Result run(int pairs) {
    ArMap office = ArMap.loadBundled("office");
    NavigationMap nav = NavigationMap.build(office, 100, 300, 1000, 4);
    ArPose home = office.findHomePose().orElseThrow();
    int reached = 0;
    List<Double> seconds = new ArrayList<>();
    List<Double> errors = new ArrayList<>();
    List<String> failures = new ArrayList<>();
    for (int i = 1; i <= pairs; i++) {
      SplittableRandom rng = new SplittableRandom(500 + i);
      ArPose start;
      ArPose goal;
      while (true) {
        start = BenchSupport.freePose(nav, 500, rng);
        goal = BenchSupport.freePose(nav, 500, rng);
        if (start.findDistanceTo(goal) >= 5000
            && BenchSupport.route(nav, home, start) != null
            && BenchSupport.route(nav, start, goal) != null) {
          break;
        }
      }
      SimulatedRobot sim = LocalizationBench.world(office, i, start);
      try {
        ArSonarLocalizationTask loc =
            ArSonarLocalizationTask.builder(sim.robot(), office)
                .mode(ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS)
                .seed(i)
                .build();
        ArPathPlanningTask path =
            ArPathPlanningTask.builder(sim.robot(), office)
                .mode(ArPathPlanningTask.PlanMode.SYNCHRONOUS)
                .build();
        sim.runMillis(1000);
        // As an operator would: "the robot is about here" (within 10 cm and 3 degrees).
        loc.localizeRobotAtPose(
            new ArPose(start.x() + 70, start.y() - 70, start.th() + 3), 150, 150, 5);
        long t0 = sim.world().getClock().nanoTime();
        path.pathPlanToPose(goal, false);
        sim.runUntil(() -> !path.isActive(), Duration.ofMinutes(4));
        double s = (sim.world().getClock().nanoTime() - t0) / 1e9;
        if (path.getState() == PathPlanningState.REACHED_GOAL) {
          reached++;
          seconds.add(s);
          errors.add(sim.sim().getTruePose().findDistanceTo(goal));
        } else {
          failures.add(
              String.format(
                  java.util.Locale.ROOT,
                  "#%d %s -> %s: %s",
                  i,
                  fmt(start),
                  fmt(goal),
                  path.getStatusString()));
        }
        path.close();
        loc.close();
      } finally {
        LocalizationBench.close(sim);
      }
    }
    return new Result(
        pairs, reached, BenchSupport.mean(seconds), BenchSupport.mean(errors), failures);
  }

  private static String fmt(ArPose p) {
    return String.format(java.util.Locale.ROOT, "(%.0f, %.0f)", p.x(), p.y());
  }
}
