package org.jaria.arnl;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.action.ArActionDesired;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.plan.LocalPlanner;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;

/**
 * One cycle of path following, for {@link ArPathPlanningTask}'s action: arrival and the final turn
 * to the goal heading, progress watching, replanning when the path ahead is blocked or the robot
 * makes no progress, and the local planner's command. Runs on the robot's cycle under the task's
 * lock.
 */
final class PathFollower {

  private static final long BLOCKED_REPLAN = TimeUnit.SECONDS.toNanos(3);
  private static final long REPLAN_COOLDOWN = TimeUnit.SECONDS.toNanos(3);
  private static final double LOOK_FOR_BLOCKS = 2500;
  private static final long STUCK_BEFORE_BACKUP = TimeUnit.MILLISECONDS.toNanos(1500);
  private static final long BACKUP_TIME = TimeUnit.MILLISECONDS.toNanos(1200);
  private static final double BACKUP_SPEED = 150;

  /** Inside this share of the goal tolerance the goal is reached at once. */
  static final double FINAL_SHARE = 0.25;

  /** Longest time spent closing in once inside the goal tolerance. */
  private static final long FINAL_APPROACH = TimeUnit.SECONDS.toNanos(3);

  private PathFollower() {}

  static ArActionDesired step(GoalKeeper t, GoalRun run, ArActionDesired d, List<Runnable> notify) {
    d.reset();
    PathPlanningState s = t.stateLocked();
    if (s == PathPlanningState.PLANNING_PATH) {
      return stop(d);
    }
    if (s != PathPlanningState.MOVING_TO_GOAL) {
      if (run.stopCycles > 0) {
        run.stopCycles--;
        return stop(d);
      }
      return null;
    }
    ArRobot robot = t.robot();
    PathPlanningParams p = t.params();
    ArPose pose = robot.getPose();
    long now = robot.getClock().nanoTime();
    double maxRot = p.maxRotSpeed.getDouble();
    double tol = p.goalDistanceTolerance.getDouble();
    double dGoal = pose.findDistanceTo(run.goal);
    if (dGoal <= tol && run.withinSince < 0) {
      run.withinSince = now;
    }
    if (run.aligning || (dGoal <= tol && arrived(run, pose, dGoal, tol, now))) {
      if (run.headingFlag) {
        double err = ArMath.subAngle(run.goal.th(), pose.th());
        if (Math.abs(err) > p.goalAngleTolerance.getDouble()) {
          run.aligning = true;
          double w = ArMath.clamp(1.5 * err, -maxRot, maxRot);
          if (Math.abs(w) < 8) {
            w = Math.signum(w) * 8;
          }
          d.setVel(0);
          d.setRotVel(w);
          return d;
        }
      }
      t.finish(PathPlanningState.REACHED_GOAL, "Arrived at " + run.name, notify);
      return stop(d);
    }
    if (now < run.backupUntil) {
      d.setVel(-BACKUP_SPEED);
      d.setRotVel(0);
      return d;
    }
    PlannedPath path = t.pathLocked();
    if (path == null) {
      return stop(d);
    }
    NavigationMap nav = t.navigationMap();
    SensedObstacles sensed = t.sensed();
    sensed.collect(
        pose,
        nav,
        p.useSonar.getBool(),
        p.collisionRange.getDouble(),
        p.mapMatchDistance.getDouble());
    run.index = path.closestIndex(pose.x(), pose.y(), run.index, 40);
    double remaining =
        path.length()
            - path.distanceTo(run.index)
            + Math.hypot(pose.x() - path.x(run.index), pose.y() - path.y(run.index));
    if (run.bestRemaining == Double.MAX_VALUE) {
      // First look along a new path: a baseline, not progress.
      run.bestRemaining = remaining;
    } else if (remaining < run.bestRemaining - 150) {
      run.bestRemaining = remaining;
      run.lastProgressNanos = now;
    }
    long secsToFail = (long) (p.secsToFail.getDouble() * 1e9);
    if (now - run.lastProgressNanos > secsToFail) {
      t.replan(
          String.format(Locale.ROOT, "no progress for %.0f s", p.secsToFail.getDouble()),
          true,
          notify);
    } else if (!run.replanPending && now - run.lastReplanNanos > REPLAN_COOLDOWN) {
      int blocker = blockerAhead(path, run.index, sensed, nav.grid().lethal());
      if (blocker >= 0) {
        t.replan(
            String.format(
                Locale.ROOT,
                "path blocked by an obstacle at (%.0f, %.0f)",
                sensed.xs()[blocker],
                sensed.ys()[blocker]),
            false,
            notify);
      }
    }
    if (t.stateLocked() != PathPlanningState.MOVING_TO_GOAL) {
      return stop(d);
    }
    path = t.pathLocked();
    run.index = path.closestIndex(pose.x(), pose.y(), run.index, 40);
    double speedCap =
        Math.sqrt(2 * p.transDecel.getDouble() * Math.max(0, dGoal - 0.5 * FINAL_SHARE * tol)) + 40;
    LocalPlanner.Command cmd =
        t.localPlanner()
            .plan(
                pose.x(),
                pose.y(),
                pose.th(),
                robot.getVel(),
                robot.getRotVel(),
                path,
                run.index,
                speedCap,
                nav,
                sensed.xs(),
                sensed.ys(),
                sensed.count(),
                p.localParams(t.halfWidth(), t.lengthFront(), t.lengthRear()));
    t.setSearchArea(t.localPlanner().searchArea());
    if (cmd.blocked()) {
      if (run.blockedSince < 0) {
        run.blockedSince = now;
      } else if (now - run.blockedSince > BLOCKED_REPLAN && !run.replanPending) {
        run.blockedSince = -1;
        t.replan("the way ahead is blocked", true, notify);
      }
    } else {
      run.blockedSince = -1;
    }
    if (isStuck(robot, cmd)) {
      if (run.stuckSince < 0) {
        run.stuckSince = now;
      } else if (now - run.stuckSince > STUCK_BEFORE_BACKUP
          && rearClear(pose, nav, sensed, t.halfWidth(), p)) {
        // Wedged against something (often after turning towards a newly seen obstacle): back off
        // a little so that the robot has room to turn.
        run.stuckSince = -1;
        run.backupUntil = now + BACKUP_TIME;
        run.backups++;
        d.setVel(-BACKUP_SPEED);
        d.setRotVel(0);
        return d;
      }
    } else {
      run.stuckSince = -1;
    }
    d.setVel(cmd.vel());
    d.setRotVel(cmd.rotVel());
    return d;
  }

  /**
   * Within the goal tolerance, whether to stop here: once well inside it ({@link #FINAL_SHARE}), or
   * when getting closer is no longer happening — the robot moves away again, the goal is off to a
   * side (no spinning on the spot for the last few centimetres), or it has been inside the
   * tolerance for a while. Stopping at the tolerance's edge would leave the robot a whole tolerance
   * short of every goal.
   */
  private static boolean arrived(GoalRun run, ArPose pose, double dGoal, double tol, long now) {
    boolean done =
        dGoal <= FINAL_SHARE * tol
            || dGoal > run.nearestGoal + 25
            || Math.abs(ArMath.subAngle(pose.findAngleTo(run.goal), pose.th())) > 60
            || now - run.withinSince > FINAL_APPROACH;
    run.nearestGoal = Math.min(run.nearestGoal, dGoal);
    return done;
  }

  /** Blocked, stalled, or commanding motion that does not happen. */
  private static boolean isStuck(ArRobot robot, LocalPlanner.Command cmd) {
    boolean commanded = Math.abs(cmd.vel()) > 1 || Math.abs(cmd.rotVel()) > 1;
    boolean moving = Math.abs(robot.getVel()) > 20 || Math.abs(robot.getRotVel()) > 3;
    return cmd.blocked()
        || robot.isLeftMotorStalled()
        || robot.isRightMotorStalled()
        || (commanded && !moving);
  }

  /** Whether the robot can back up a short way: nothing mapped or sensed right behind it. */
  private static boolean rearClear(
      ArPose pose, NavigationMap nav, SensedObstacles sensed, double half, PathPlanningParams p) {
    double th = Math.toRadians(pose.th());
    double c = Math.cos(th);
    double s = Math.sin(th);
    double rear = p.sideClearance.getDouble() + 250;
    double backX = pose.x() - c * 250;
    double backY = pose.y() - s * 250;
    if (nav.clearanceAt(backX, backY) < half + p.sideClearance.getDouble()) {
      return false;
    }
    for (int k = 0; k < sensed.count(); k++) {
      double dx = sensed.xs()[k] - pose.x();
      double dy = sensed.ys()[k] - pose.y();
      double lx = c * dx + s * dy;
      double ly = -s * dx + c * dy;
      if (lx < 0 && lx > -(rear + 350) && Math.abs(ly) < half + 50) {
        return false;
      }
    }
    return true;
  }

  /** The first sensed point within {@code lethal} of the path in the next stretch, or −1. */
  private static int blockerAhead(
      PlannedPath path, int from, SensedObstacles sensed, double lethal) {
    int n = sensed.count();
    if (n == 0) {
      return -1;
    }
    int to = path.indexAhead(from, LOOK_FOR_BLOCKS);
    double l2 = lethal * lethal;
    double[] xs = sensed.xs();
    double[] ys = sensed.ys();
    for (int i = from; i <= to; i++) {
      for (int k = 0; k < n; k++) {
        double dx = xs[k] - path.x(i);
        double dy = ys[k] - path.y(i);
        if (dx * dx + dy * dy < l2) {
          return k;
        }
      }
    }
    return -1;
  }

  private static ArActionDesired stop(ArActionDesired d) {
    d.setVel(0);
    d.setRotVel(0);
    return d;
  }
}
