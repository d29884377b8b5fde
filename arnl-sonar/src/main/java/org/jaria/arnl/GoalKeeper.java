package org.jaria.arnl;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.jaria.action.ArActionDesired;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArPathPlanningTask.PlanMode;
import org.jaria.arnl.plan.LocalPlanner;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The goal state machine behind {@link ArPathPlanningTask}: accepting or refusing goals, asking for
 * plans (inline or on the planning thread) and installing them, replanning, and ending goals with
 * their callbacks. Everything here runs under one lock; callbacks are run after it is released. The
 * published fields are volatile: written under the lock, read by any thread without it.
 */
final class GoalKeeper {

  private static final Logger log = LoggerFactory.getLogger(ArPathPlanningTask.class);

  private static final int STOP_CYCLES = 10;

  private final ArPathPlanningTask task;
  private final ArRobot robot;
  private final ArMap map;
  private final PathPlanningParams params;
  private final PlanMode mode;
  private final ReentrantLock lock = new ReentrantLock();
  private final PlanComputer computer = new PlanComputer();
  private final LocalPlanner local = new LocalPlanner();

  // Its points are written by fire() and read by sensedPoses(), both under the lock.
  @GuardedBy("lock")
  private final SensedObstacles sensed;

  private final ExecutorService executor;

  @GuardedBy("lock")
  private NavigationMap nav;

  @GuardedBy("lock")
  private boolean navDirty = true;

  // GoalRun has no lock of its own: reaching it through this field is what Error Prone checks.
  @GuardedBy("lock")
  private final GoalRun run = new GoalRun();

  // Published for any thread (written under the lock).
  private volatile PathPlanningState state = PathPlanningState.NOT_INITIALIZED;
  private volatile String status = "No goal yet";
  private volatile String failure = "";
  private volatile ArPose goal = ArPose.ORIGIN;
  private volatile PlannedPath path;
  private volatile double[] searchArea;
  private volatile double lastPlanMillis;

  GoalKeeper(
      ArPathPlanningTask task, ArRobot robot, ArMap map, PathPlanningParams params, PlanMode mode) {
    this.task = task;
    this.robot = robot;
    this.map = map;
    this.params = params;
    this.mode = mode;
    this.sensed = new SensedObstacles(robot);
    if (mode == PlanMode.THREADED) {
      String name = "pathPlanning-" + robot.getName();
      executor =
          Executors.newSingleThreadExecutor(
              r -> {
                Thread t = new Thread(r, name);
                t.setDaemon(true);
                return t;
              });
    } else {
      executor = null;
    }
  }

  boolean markDirty() {
    lock.lock();
    try {
      navDirty = true;
    } finally {
      lock.unlock();
    }
    return true;
  }

  /**
   * The navigation maps, rebuilt if parameters changed. For {@link PathFollower}, which runs inside
   * {@link #fire} with the lock held: the lock is reentrant, so taking it again changes nothing and
   * lets Error Prone check the access.
   */
  NavigationMap navigationMap() {
    lock.lock();
    try {
      return navigationMapLocked();
    } finally {
      lock.unlock();
    }
  }

  @GuardedBy("lock")
  private NavigationMap navigationMapLocked() {
    if (nav == null || navDirty) {
      long t0 = System.nanoTime();
      double half = halfWidth();
      nav =
          NavigationMap.build(
              map,
              params.planRes.getDouble(),
              half + params.planPadding.getDouble(),
              params.planFreeSpace.getDouble(),
              params.clearanceCost.getDouble());
      navDirty = false;
      log.info("built navigation maps in {} ms", (System.nanoTime() - t0) / 1_000_000);
    }
    return nav;
  }

  /** Distance from the robot's centre to its front, mm. */
  double lengthFront() {
    return robot.getRobotParams().getRobotLengthFront();
  }

  /** Distance from the robot's centre to its rear, mm. */
  double lengthRear() {
    return robot.getRobotParams().getRobotLengthRear();
  }

  double halfWidth() {
    double w = params.width.getDouble();
    return (w > 0 ? w : robot.getRobotParams().getRobotWidth()) / 2;
  }

  boolean startGoal(ArPose goalPose, boolean headingFlag, String name) {
    List<Runnable> notify = new ArrayList<>();
    PlanComputer.Request request;
    boolean accepted;
    lock.lock();
    try {
      interruptLocked(notify, "replaced by a new goal");
      NavigationMap n = navigationMapLocked();
      run.begin(goalPose, headingFlag, name, robot.getClock().nanoTime());
      run.replanCounts = true;
      goal = goalPose;
      path = null;
      for (Consumer<ArPose> cb : task.newGoalCBs) {
        notify.add(() -> cb.accept(goalPose));
      }
      String refusal = checkGoal(n, goalPose);
      if (refusal != null) {
        PathPlanningState s =
            n.inBounds(goalPose.x(), goalPose.y())
                ? PathPlanningState.GOAL_IN_OBSTACLE
                : PathPlanningState.GOAL_OUT_OF_BOUNDS;
        finishLocked(s, "Cannot go to " + name + ": " + refusal, notify);
        request = null;
        accepted = false;
      } else {
        setState(PathPlanningState.PLANNING_PATH, "Planning a path to " + name);
        request = newRequestLocked(n);
        accepted = true;
      }
    } finally {
      lock.unlock();
    }
    runAll(notify);
    if (request != null) {
      submit(request);
      if (mode == PlanMode.SYNCHRONOUS) {
        return state != PathPlanningState.FAILED_PLAN;
      }
    }
    return accepted;
  }

  /** Why the goal is refused, or null if it is acceptable. */
  private String checkGoal(NavigationMap n, ArPose g) {
    if (!n.inBounds(g.x(), g.y())) {
      return "it lies outside the map " + PlanComputer.fmt(g);
    }
    Optional<ArMapObject> area = n.forbiddenAreaAt(g.x(), g.y());
    if (area.isPresent()) {
      return "it lies inside a forbidden area "
          + PlanComputer.fmt(area.get().fromPose())
          + "-"
          + PlanComputer.fmt(area.get().toPose());
    }
    int k = n.grid().spec().indexOf(g.x(), g.y());
    if (n.grid().nearestFree(k, PlanComputer.GOAL_SNAP) < 0) {
      return String.format(
          Locale.ROOT,
          "it is too close to a wall or forbidden line (%.0f mm; the robot needs %.0f mm)",
          n.grid().clearance(k),
          n.grid().lethal());
    }
    return null;
  }

  /** A plan request from the robot's pose to the goal, with the remembered obstacles. */
  @GuardedBy("lock")
  private PlanComputer.Request newRequestLocked(NavigationMap n) {
    long id = run.nextPlanId();
    return new PlanComputer.Request(
        id,
        robot.getPose(),
        run.goal,
        n,
        run.stampXs(),
        run.stampYs(),
        run.stampCount(),
        Math.max(0, params.planPadding.getDouble() - params.sideClearance.getDouble()));
  }

  private void submit(PlanComputer.Request r) {
    if (mode == PlanMode.SYNCHRONOUS) {
      accept(computer.compute(r));
    } else {
      executor.execute(() -> accept(computer.compute(r)));
    }
  }

  /** A plan came back (on the planning thread): install it, or fail. */
  private void accept(PlanComputer.Result r) {
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      applyResultLocked(r, notify);
    } finally {
      lock.unlock();
    }
    runAll(notify);
  }

  @GuardedBy("lock")
  private void applyResultLocked(PlanComputer.Result r, List<Runnable> notify) {
    if (r.id() != run.planId
        || (state != PathPlanningState.PLANNING_PATH
            && state != PathPlanningState.MOVING_TO_GOAL)) {
      return;
    }
    lastPlanMillis = r.millis();
    run.replanPending = false;
    if (r.path() != null) {
      path = r.path();
      run.newPath(robot.getClock().nanoTime(), run.replanCounts);
      if (state == PathPlanningState.PLANNING_PATH) {
        setState(PathPlanningState.MOVING_TO_GOAL, "Going to " + run.name);
      }
      log.debug(
          "planned {} mm to {} in {} ms ({} cells)",
          Math.round(r.path().length()),
          run.name,
          r.millis(),
          r.expanded());
    } else if (state == PathPlanningState.PLANNING_PATH) {
      finishLocked(
          PathPlanningState.FAILED_PLAN,
          "Failed to plan to " + run.name + ": " + r.failure(),
          notify);
    } else if (run.replans >= params.maxReplans.getInt()) {
      finishLocked(
          PathPlanningState.FAILED_MOVE,
          "Failed to get to " + run.name + ": " + r.failure(),
          notify);
    } else {
      // Replanning around the sensed obstacles failed: forget them; the old path stays.
      run.clearStamps();
    }
  }

  @GuardedBy("lock")
  private void interruptLocked(List<Runnable> notify, String why) {
    if (state != PathPlanningState.PLANNING_PATH && state != PathPlanningState.MOVING_TO_GOAL) {
      return;
    }
    ArPose g = run.goal;
    run.nextPlanId();
    setState(PathPlanningState.ABORTED_PATHPLAN, "Stopped going to " + run.name + ": " + why);
    failure = status;
    run.stopCycles = STOP_CYCLES;
    for (Consumer<ArPose> cb : task.goalInterruptedCBs) {
      notify.add(() -> cb.accept(g));
    }
    notify.addAll(task.goalFinishedCBs);
  }

  /**
   * Ends the goal in a final state, with callbacks (for {@link PathFollower}: see {@link
   * #navigationMap}).
   */
  void finish(PathPlanningState s, String message, List<Runnable> notify) {
    lock.lock();
    try {
      finishLocked(s, message, notify);
    } finally {
      lock.unlock();
    }
  }

  @GuardedBy("lock")
  private void finishLocked(PathPlanningState s, String message, List<Runnable> notify) {
    ArPose g = run.goal;
    run.nextPlanId();
    run.stopCycles = STOP_CYCLES;
    setState(s, message);
    if (s == PathPlanningState.REACHED_GOAL) {
      failure = "";
      for (Consumer<ArPose> cb : task.goalDoneCBs) {
        notify.add(() -> cb.accept(g));
      }
    } else {
      failure = message;
      log.info(message);
      for (Consumer<ArPose> cb : task.goalFailedCBs) {
        notify.add(() -> cb.accept(g));
      }
    }
    notify.addAll(task.goalFinishedCBs);
  }

  private void setState(PathPlanningState s, String message) {
    state = s;
    status = message;
  }

  /**
   * Asks for a new plan from where the robot is, avoiding what is sensed now (for {@link
   * PathFollower}; see {@link #navigationMap}).
   *
   * @param counts whether this replan counts towards {@code MaxReplans} (lack of progress does; a
   *     path that merely passes a newly seen obstacle does not)
   */
  void replan(String why, boolean counts, List<Runnable> notify) {
    lock.lock();
    try {
      replanLocked(why, counts, notify);
    } finally {
      lock.unlock();
    }
  }

  @GuardedBy("lock")
  private void replanLocked(String why, boolean counts, List<Runnable> notify) {
    long now = robot.getClock().nanoTime();
    run.totalReplans++;
    if (counts) {
      run.replans++;
      if (run.replans > params.maxReplans.getInt()) {
        finishLocked(
            PathPlanningState.FAILED_MOVE,
            "Failed to get to "
                + run.name
                + ": "
                + why
                + " (gave up after "
                + (run.replans - 1)
                + " replans)",
            notify);
        return;
      }
    }
    log.debug("replanning to {}: {}", run.name, why);
    run.stamp(sensed.xs(), sensed.ys(), sensed.count(), now);
    run.replanPending = true;
    run.replanCounts = counts;
    run.lastReplanNanos = now;
    if (counts) {
      run.progressReset(now);
    }
    PlanComputer.Request r = newRequestLocked(navigationMapLocked());
    if (mode == PlanMode.SYNCHRONOUS) {
      applyResultLocked(computer.compute(r), notify);
    } else {
      executor.execute(() -> accept(computer.compute(r)));
    }
  }

  // ================================================================ the action

  /** One cycle of the path-following action; returns what to ask of the robot, or null. */
  ArActionDesired fire(ArActionDesired desired) {
    List<Runnable> notify = new ArrayList<>();
    ArActionDesired out;
    lock.lock();
    try {
      // The map is used to recognise echoes of mapped walls once it exists (built for a goal).
      sensed.noteSonar(nav == null || navDirty ? null : nav, params.mapMatchDistance.getDouble());
      out = PathFollower.step(this, run, desired, notify);
    } finally {
      lock.unlock();
    }
    runAll(notify);
    return out;
  }

  PathPlanningState stateLocked() {
    return state;
  }

  PlannedPath pathLocked() {
    return path;
  }

  void setSearchArea(double[] a) {
    searchArea = a;
  }

  ArRobot robot() {
    return robot;
  }

  PathPlanningParams params() {
    return params;
  }

  LocalPlanner localPlanner() {
    return local;
  }

  /**
   * What the sensors see (for {@link PathFollower}, see {@link #navigationMap}; and to add or
   * remove range devices, which its thread-safe device list allows from any thread).
   */
  SensedObstacles sensed() {
    lock.lock();
    try {
      return sensed;
    } finally {
      lock.unlock();
    }
  }

  private static void runAll(List<Runnable> cbs) {
    for (Runnable r : cbs) {
      try {
        r.run();
      } catch (RuntimeException e) {
        log.error("path planning callback threw", e);
      }
    }
  }

  /** Stops following the path (ARNL's {@code cancelPathPlan}); the robot stops. */
  void cancelPathPlan() {
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      interruptLocked(notify, "cancelled");
    } finally {
      lock.unlock();
    }
    runAll(notify);
  }

  /**
   * Tells path planning that localization failed (ARNL's {@code trackingFailed}): the current goal
   * fails (FAILED_MOVE) and the robot stops, since the pose it plans from is not to be trusted.
   *
   * @param failedTimes how many localization updates failed (for the message)
   */
  void trackingFailed(int failedTimes) {
    List<Runnable> notify = new ArrayList<>();
    lock.lock();
    try {
      if (state == PathPlanningState.PLANNING_PATH || state == PathPlanningState.MOVING_TO_GOAL) {
        finishLocked(
            PathPlanningState.FAILED_MOVE,
            "Failed to get to "
                + run.name
                + ": localization lost"
                + (failedTimes > 0 ? " (" + failedTimes + " failed updates)" : ""),
            notify);
      }
    } finally {
      lock.unlock();
    }
    runAll(notify);
  }

  /** A goal of the map by name (case-insensitive), or a status saying there is none. */
  Optional<ArMapObject> findGoal(String goalName) {
    Optional<ArMapObject> o =
        map.getGoals().stream()
            .filter(g -> g.name().equalsIgnoreCase(goalName.strip()))
            .findFirst();
    if (o.isEmpty()) {
      List<String> names = map.getGoals().stream().map(ArMapObject::name).toList();
      status = "There is no goal called '" + goalName + "' on the map; goals: " + names;
      failure = status;
    }
    return o;
  }

  PathPlanningState state() {
    return state;
  }

  String status() {
    return status;
  }

  String failure() {
    return failure;
  }

  ArPose goal() {
    return goal;
  }

  PlannedPath path() {
    return path;
  }

  double[] searchArea() {
    return searchArea;
  }

  double lastPlanMillis() {
    return lastPlanMillis;
  }

  int replanCount() {
    lock.lock();
    try {
      return run.totalReplans;
    } finally {
      lock.unlock();
    }
  }

  /** The sensed obstacle points as poses, read under the lock. */
  List<ArPose> sensedPoses() {
    lock.lock();
    try {
      List<ArPose> out = new ArrayList<>(sensed.count());
      for (int i = 0; i < sensed.count(); i++) {
        out.add(new ArPose(sensed.xs()[i], sensed.ys()[i]));
      }
      return out;
    } finally {
      lock.unlock();
    }
  }

  /** Stops the planning thread. */
  void shutdown() {
    if (executor != null) {
      executor.shutdownNow();
      try {
        if (!executor.awaitTermination(5, TimeUnit.SECONDS)) {
          log.warn("the path planning thread did not stop within 5 s");
        }
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }
}
