package org.jaria.tools.examples;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.jaria.arnl.ArActionLost;
import org.jaria.arnl.ArActionSlowDownWhenNotCertain;
import org.jaria.arnl.ArBaseLocalizationTask;
import org.jaria.arnl.ArForbiddenRangeDevice;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.range.ArBumpers;
import org.jaria.range.ArIRs;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;

/**
 * The robot set up as in the thesis's server program: sonar, bumpers, IRs (if the robot has them)
 * and a forbidden-range device; sonar localization; path planning with the lost and slow-down
 * actions. Then {@link #visit} drives to the goals.
 */
final class Navigator implements AutoCloseable {

  private static final long PROGRESS_EVERY_MS = 5000;

  private final ArRobot robot;
  private final ArMap map;
  private final ArSonarLocalizationTask loc;
  private final ArPathPlanningTask path;

  private Navigator(
      ArRobot robot, ArMap map, ArSonarLocalizationTask loc, ArPathPlanningTask path) {
    this.robot = robot;
    this.map = map;
    this.loc = loc;
    this.path = path;
  }

  static Navigator create(
      ArRobot robot,
      ArMap map,
      ArBaseLocalizationTask.UpdateMode locMode,
      ArPathPlanningTask.PlanMode planMode,
      long seed) {
    ArSonarDevice sonar = new ArSonarDevice();
    ArBumpers bumpers = new ArBumpers();
    ArForbiddenRangeDevice forbidden = new ArForbiddenRangeDevice(map);
    robot.lock();
    try {
      robot.addRangeDevice(sonar);
      robot.addRangeDevice(bumpers);
      robot.addRangeDevice(forbidden);
    } finally {
      robot.unlock();
    }
    ArSonarLocalizationTask loc =
        ArSonarLocalizationTask.builder(robot, map).sonar(sonar).mode(locMode).seed(seed).build();
    ArPathPlanningTask path =
        ArPathPlanningTask.builder(robot, map).sonar(sonar).mode(planMode).build();
    path.addRangeDevice(bumpers, ArPathPlanningTask.RangeType.CURRENT);
    path.addRangeDevice(forbidden, ArPathPlanningTask.RangeType.CURRENT);
    if (robot.getRobotParams().getNumIR() > 0) {
      ArIRs irs = new ArIRs();
      robot.addRangeDevice(irs);
      path.addRangeDevice(irs, ArPathPlanningTask.RangeType.CURRENT);
    }
    path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
    path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
    return new Navigator(robot, map, loc, path);
  }

  /** Localizes at home, then drives to every goal in turn. */
  NavigateDemo.Result visit(
      NavigateDemo.Options o, PrintStream out, NavigateDemo.Stepper step, SimRobot truth) {
    robot.enableMotors();
    step.run(1500);
    boolean home = loc.localizeRobotAtHomeBlocking();
    out.printf(
        Locale.ROOT,
        "Localized at home: %s, pose %s, score %.2f%n",
        home ? "yes" : "NO (continuing with the best guess)",
        NavigateDemo.fmt(robot.getPose()),
        loc.getLocalizationScore());
    List<NavigateDemo.GoalOutcome> outcomes = new ArrayList<>();
    for (String g : o.goals()) {
      outcomes.add(goTo(g, o, out, step, truth));
    }
    long reached = outcomes.stream().filter(NavigateDemo.GoalOutcome::reached).count();
    out.printf(Locale.ROOT, "Done: %d of %d goals reached.%n", reached, outcomes.size());
    return new NavigateDemo.Result(home, outcomes);
  }

  private NavigateDemo.GoalOutcome goTo(
      String goal,
      NavigateDemo.Options o,
      PrintStream out,
      NavigateDemo.Stepper step,
      SimRobot truth) {
    long start = robot.getClock().nanoTime();
    Optional<ArPose> target = goalPose(goal);
    if (target.isEmpty()) {
      path.pathPlanToGoal(goal);
      out.printf(Locale.ROOT, "Goal %s: %s%n", goal, path.getStatusString());
      return new NavigateDemo.GoalOutcome(
          goal,
          PathPlanningState.FAILED_PLAN,
          path.getStatusString(),
          0,
          Double.NaN,
          Double.NaN,
          Double.NaN);
    }
    boolean named = map.getGoals().stream().anyMatch(g -> g.name().equalsIgnoreCase(goal.strip()));
    boolean accepted =
        named
            ? path.pathPlanToGoal(goal)
            : path.pathPlanToPose(target.get(), goal.chars().filter(c -> c == ',').count() >= 2);
    out.printf(Locale.ROOT, "Goal %s: %s%n", goal, path.getStatusString());
    long limit = o.goalTimeout().toMillis();
    long elapsed = 0;
    long nextReport = PROGRESS_EVERY_MS;
    while (accepted && path.isActive() && elapsed < limit) {
      step.run(100);
      elapsed = (robot.getClock().nanoTime() - start) / 1_000_000;
      if (elapsed >= nextReport) {
        nextReport += PROGRESS_EVERY_MS;
        out.printf(
            Locale.ROOT,
            "  %6.1f s  at %s  %s, %.1f m to go, localization score %.2f%n",
            elapsed / 1000.0,
            NavigateDemo.fmt(robot.getPose()),
            path.getState(),
            path.getDistanceToGoal() / 1000,
            loc.getLocalizationScore());
      }
    }
    if (path.isActive()) {
      path.cancelPathPlan();
      out.printf(Locale.ROOT, "  gave up after %d s%n", TimeUnit.MILLISECONDS.toSeconds(limit));
    }
    step.run(500);
    double seconds = (robot.getClock().nanoTime() - start) / 1e9;
    ArPose goalPose = path.getCurrentGoal();
    ArPose believed = robot.getPose();
    ArPose actual = truth == null ? believed : truth.getTruePose();
    boolean reached = path.getState() == PathPlanningState.REACHED_GOAL;
    double goalError = reached ? actual.findDistanceTo(goalPose) : Double.NaN;
    double locError = truth == null ? Double.NaN : actual.findDistanceTo(believed);
    double locDeg = truth == null ? Double.NaN : NavigateDemo.headingError(actual, believed);
    if (reached) {
      out.printf(
          Locale.ROOT,
          "  reached in %.1f s: final position error %.0f mm%s%n",
          seconds,
          goalError,
          truth == null
              ? " (by localization)"
              : String.format(
                  Locale.ROOT,
                  " (true pose %s; localization error %.0f mm, %.1f°)",
                  NavigateDemo.fmt(actual),
                  locError,
                  locDeg));
    } else {
      out.printf(Locale.ROOT, "  %s: %s%n", path.getState(), path.getStatusString());
    }
    return new NavigateDemo.GoalOutcome(
        goal, path.getState(), path.getStatusString(), seconds, goalError, locError, locDeg);
  }

  /** A named goal's pose, or a pose written "x,y" or "x,y,th". */
  private Optional<ArPose> goalPose(String goal) {
    for (ArMapObject g : map.getGoals()) {
      if (g.name().equalsIgnoreCase(goal.strip())) {
        return Optional.of(g.pose());
      }
    }
    List<String> v = new ArrayList<>();
    int from = 0;
    for (int k = goal.indexOf(','); k >= 0; k = goal.indexOf(',', from)) {
      v.add(goal.substring(from, k));
      from = k + 1;
    }
    v.add(goal.substring(from));
    if (v.size() < 2 || v.size() > 3) {
      return Optional.empty();
    }
    try {
      double x = Double.parseDouble(v.get(0).strip());
      double y = Double.parseDouble(v.get(1).strip());
      double th = v.size() == 3 ? Double.parseDouble(v.get(2).strip()) : 0;
      return Optional.of(new ArPose(x, y, th));
    } catch (NumberFormatException e) {
      return Optional.empty();
    }
  }

  @Override
  public void close() {
    path.close();
    loc.close();
  }
}
