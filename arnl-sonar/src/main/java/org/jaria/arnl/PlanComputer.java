package org.jaria.arnl;

import java.util.Locale;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.arnl.plan.AStarPlanner;
import org.jaria.arnl.plan.CostGrid;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PathSmoother;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArPose;

/**
 * Computes one global plan: start and goal cells (moved to the nearest cell the robot fits in if
 * they are just too close to something), A* on the cost grid with any sensed obstacles stamped in,
 * then smoothing. Runs on the planning thread, or inline in synchronous mode. Not thread-safe (it
 * reuses the A* arrays).
 */
final class PlanComputer {

  /** A request: plan from {@code start} to {@code goal} avoiding the extra obstacle points. */
  // The arrays are fresh copies made for the request and never changed.
  @SuppressWarnings("ArrayRecordComponent")
  record Request(
      long id,
      ArPose start,
      ArPose goal,
      NavigationMap nav,
      double[] ox,
      double[] oy,
      int n,
      double allowance) {}

  /** The answer: a path, or null and why not. */
  record Result(long id, PlannedPath path, String failure, double millis, int expanded) {}

  /** How far a start or goal may be moved to reach a cell the robot fits in, mm. */
  static final double START_SNAP = 1000;

  static final double GOAL_SNAP = 150;

  private final AStarPlanner astar = new AStarPlanner();

  Result compute(Request r) {
    long t0 = System.nanoTime();
    if (r.n() > 0) {
      Result around =
          compute(r, r.nav().grid().withObstacles(r.ox(), r.oy(), r.n(), r.allowance()), t0);
      if (around.path() != null) {
        return around;
      }
      // Sonar obstacles can close a gap that is really open (an echo placed beside a doorway):
      // rather than give up, plan on the map alone and let the local planner sort it out there.
    }
    return compute(r, r.nav().grid(), t0);
  }

  private Result compute(Request r, CostGrid grid, long t0) {
    GridSpec s = grid.spec();
    int start = s.indexOf(r.start().x(), r.start().y());
    if (start < 0) {
      return fail(r, t0, "the robot " + fmt(r.start()) + " is outside the map; localize it first");
    }
    int freeStart = grid.nearestFree(start, START_SNAP);
    if (freeStart < 0) {
      return fail(
          r,
          t0,
          "the robot "
              + fmt(r.start())
              + " is boxed in: no free cell within "
              + (int) START_SNAP
              + " mm (check localization, or move it by hand)");
    }
    int goal = s.indexOf(r.goal().x(), r.goal().y());
    if (goal < 0) {
      return fail(r, t0, "the goal " + fmt(r.goal()) + " is outside the map");
    }
    int freeGoal = grid.nearestFree(goal, GOAL_SNAP);
    if (freeGoal < 0) {
      return fail(
          r,
          t0,
          "the goal "
              + fmt(r.goal())
              + " is blocked: "
              + (r.n() > 0 ? "an obstacle was sensed there" : "it is too close to a wall"));
    }
    int[] cells = astar.plan(grid, freeStart, freeGoal);
    if (cells == null) {
      return fail(
          r,
          t0,
          "no path from "
              + fmt(r.start())
              + " to "
              + fmt(r.goal())
              + (r.n() > 0
                  ? ": the way is blocked by walls, forbidden lines or sensed obstacles"
                  : ": walls or forbidden lines close the goal off from the robot"));
    }
    PlannedPath path =
        PathSmoother.smooth(cells, grid, r.start().x(), r.start().y(), r.goal().x(), r.goal().y());
    return new Result(r.id(), path, "", (System.nanoTime() - t0) / 1e6, astar.expandedCount());
  }

  private Result fail(Request r, long t0, String why) {
    return new Result(r.id(), null, why, (System.nanoTime() - t0) / 1e6, astar.expandedCount());
  }

  static String fmt(ArPose p) {
    return String.format(Locale.ROOT, "(%.0f, %.0f)", p.x(), p.y());
  }
}
