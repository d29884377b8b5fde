package org.jaria.arnl;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArActionGroup;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigException;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.range.ArRangeDevice;
import org.jaria.robot.ArRobot;

/**
 * Path planning and following (SonARNL's {@code ArPathPlanningTask}): plans the cheapest safe path
 * from the robot's (localized) pose to a goal on the map, then drives it with an action ({@link
 * ArActionPlanAndMoveToGoal}) whose dynamic-window local planner avoids unmapped obstacles seen by
 * the sonar and the range devices added with {@link #addRangeDevice}, replanning around them when
 * the way is blocked.
 *
 * <pre>{@code
 * ArPathPlanningTask path = new ArPathPlanningTask(robot, sonar, map);
 * path.addGoalDoneCB(goal -> System.out.println("arrived at " + goal));
 * path.pathPlanToGoal("Lab");
 * }</pre>
 *
 * <p>Plans are computed on the task's own thread ({@link PlanMode#THREADED}, for real robots) or
 * inline ({@link PlanMode#SYNCHRONOUS}: in the caller for a new goal, in the robot's cycle for a
 * replan), which makes lockstep simulations repeatable. The local planner runs in the action, on
 * the robot's cycle. All public methods may be called from any thread; callbacks run on the thread
 * that made the change (usually the robot's cycle) and must return quickly.
 */
public final class ArPathPlanningTask implements AutoCloseable {

  /**
   * The state of path planning (ARNL's {@code PathPlanningState}, with the goal checks split out).
   */
  public enum PathPlanningState {
    /** No goal given yet. */
    NOT_INITIALIZED,
    /** Planning the initial path. */
    PLANNING_PATH,
    /** Following the path. */
    MOVING_TO_GOAL,
    /** Arrived. */
    REACHED_GOAL,
    /** No path to the goal exists. */
    FAILED_PLAN,
    /** A path existed but the robot could not follow it (blocked, no progress). */
    FAILED_MOVE,
    /** Cancelled, or replaced by another goal. */
    ABORTED_PATHPLAN,
    /** The goal lies outside the map. */
    GOAL_OUT_OF_BOUNDS,
    /** The goal lies in a forbidden area or too close to a wall for the robot. */
    GOAL_IN_OBSTACLE
  }

  /** Which readings of an added range device to avoid (ARNL's {@code RangeType}). */
  public enum RangeType {
    /** None. */
    NEITHER,
    /** The current buffer. */
    CURRENT,
    /** The cumulative buffer. */
    CUMULATIVE,
    /** Both buffers. */
    BOTH
  }

  /** Where global plans are computed. */
  public enum PlanMode {
    /** On the task's own thread (real robots). */
    THREADED,
    /** Inline: in the caller for a new goal, in the robot cycle for replans (lockstep). */
    SYNCHRONOUS
  }

  private final ArRobot robot;
  private final ArMap map;
  private final PathPlanningParams params;
  private final PlanMode mode;
  private final GoalKeeper keeper;
  private final ArActionPlanAndMoveToGoal action;
  private final ArActionGroup group;
  final CopyOnWriteArrayList<Consumer<ArPose>> goalDoneCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<Consumer<ArPose>> goalFailedCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<Consumer<ArPose>> goalInterruptedCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<Consumer<ArPose>> newGoalCBs = new CopyOnWriteArrayList<>();
  final CopyOnWriteArrayList<Runnable> goalFinishedCBs = new CopyOnWriteArrayList<>();

  /**
   * ARNL's constructor: plans on the task's own thread, default parameters in a config of its own.
   */
  public ArPathPlanningTask(ArRobot robot, ArRangeDevice sonar, ArMap map) {
    this(builder(robot, map).sonar(sonar));
  }

  private ArPathPlanningTask(Builder b) {
    this.robot = Objects.requireNonNull(b.robot, "robot");
    this.map = Objects.requireNonNull(b.map, "map");
    this.params = new PathPlanningParams(b.config == null ? new ArConfig() : b.config);
    if (!b.useSonar) {
      params.useSonar.setBool(false);
    }
    this.mode = b.mode;
    this.keeper = new GoalKeeper(this, robot, map, params, mode);
    params.getConfig().addProcessFileCB(keeper::markDirty, 40);
    for (var a : List.of(params.planRes, params.planFreeSpace, params.clearanceCost)) {
      a.addChangeListener(x -> keeper.markDirty());
    }
    params.width.addChangeListener(x -> keeper.markDirty());
    params.planPadding.addChangeListener(x -> keeper.markDirty());
    this.action = new ArActionPlanAndMoveToGoal(this);
    this.group = new ArActionGroup(robot);
    group.addAction(action, 50);
  }

  /** A builder with more options than ARNL's constructor. */
  public static Builder builder(ArRobot robot, ArMap map) {
    return new Builder(robot, map);
  }

  /** Options for {@link ArPathPlanningTask}. */
  public static final class Builder {
    private final ArRobot robot;
    private final ArMap map;
    private ArConfig config;
    private PlanMode mode = PlanMode.THREADED;
    private boolean useSonar = true;

    private Builder(ArRobot robot, ArMap map) {
      this.robot = robot;
      this.map = map;
    }

    /**
     * The sonar whose echoes the robot avoids, or null to plan and drive without sonar (as in ARNL,
     * where a null sonar means none). The echoes are read from the robot's SIPs, so a sonar given
     * must not belong to another robot. With a sonar, the {@code UseSonar} parameter still switches
     * it off and on; null sets that parameter to false.
     *
     * @throws IllegalArgumentException if {@code sonar} was added to another robot
     */
    public Builder sonar(ArRangeDevice sonar) {
      if (sonar != null && sonar.getRobot() != null && sonar.getRobot() != robot) {
        throw new IllegalArgumentException(
            "the sonar '"
                + sonar.getName()
                + "' belongs to robot '"
                + sonar.getRobot().getName()
                + "': pass the sonar added to the robot that plans, or null for none");
      }
      useSonar = sonar != null;
      return this;
    }

    /** Registers the parameters in {@code c} (default: a config of the task's own). */
    public Builder config(ArConfig c) {
      config = c;
      return this;
    }

    /** Threaded (default) or synchronous planning. */
    public Builder mode(PlanMode m) {
      mode = Objects.requireNonNull(m, "mode");
      return this;
    }

    /** Creates the task and adds its action to the robot. */
    public ArPathPlanningTask build() {
      return new ArPathPlanningTask(this);
    }
  }

  /** The goal state machine (package use: the action and the follower). */
  GoalKeeper keeper() {
    return keeper;
  }

  // ================================================================ goals

  /**
   * Plans a path to {@code goalPose} and starts following it.
   *
   * @param headingFlag whether to turn to the goal's heading on arrival
   * @return false if the goal was refused at once (outside the map, in an obstacle) or, in
   *     synchronous mode, if no path exists; see {@link #getState()} and {@link #getStatusString()}
   */
  public boolean pathPlanToPose(ArPose goalPose, boolean headingFlag) {
    return keeper.startGoal(goalPose, headingFlag, PlanComputer.fmt(goalPose));
  }

  /**
   * Plans to the goal called {@code goalName} on the map (Goal or GoalWithHeading,
   * case-insensitive; the heading of a GoalWithHeading is kept on arrival).
   *
   * @return false if there is no such goal or it was refused (see {@link #pathPlanToPose})
   */
  public boolean pathPlanToGoal(String goalName) {
    Optional<ArMapObject> o = keeper.findGoal(goalName);
    if (o.isEmpty()) {
      return false;
    }
    ArMapObject g = o.get();
    return keeper.startGoal(g.pose(), g.type().equals("GoalWithHeading"), "'" + g.name() + "'");
  }

  /** Stops following the path (ARNL's {@code cancelPathPlan}); the robot stops. */
  public void cancelPathPlan() {
    keeper.cancelPathPlan();
  }

  /**
   * Tells path planning that localization failed (ARNL's {@code trackingFailed}): the current goal
   * fails (FAILED_MOVE) and the robot stops, since the pose it plans from is not to be trusted.
   *
   * @param failedTimes how many localization updates failed (for the message)
   */
  public void trackingFailed(int failedTimes) {
    keeper.trackingFailed(failedTimes);
  }

  /** One cycle of the path-following action; returns what to ask of the robot, or null. */
  ArActionDesired fire(ArActionDesired desired) {
    return keeper.fire(desired);
  }

  // ================================================================ state and display

  /** The state. */
  public PathPlanningState getState() {
    return keeper.state();
  }

  /** What the task is doing or why it failed, for people. */
  public String getStatusString() {
    return keeper.status();
  }

  /** Why the last goal failed ("" if it did not). */
  public String getFailureString() {
    return keeper.failure();
  }

  /** The current (or last) goal. */
  public ArPose getCurrentGoal() {
    return keeper.goal();
  }

  /** Whether a goal is being planned or followed. */
  public boolean isActive() {
    PathPlanningState s = keeper.state();
    return s == PathPlanningState.PLANNING_PATH || s == PathPlanningState.MOVING_TO_GOAL;
  }

  /**
   * How far the robot still has to go to the current (or last) goal, mm: along the path if there is
   * one, else in a straight line. For progress displays.
   */
  public double getDistanceToGoal() {
    ArPose here = robot.getPose();
    PlannedPath p = keeper.path();
    return p == null ? here.findDistanceTo(keeper.goal()) : p.remainingFrom(here.x(), here.y());
  }

  /** The current path as poses (empty if none). */
  public List<ArPose> getCurrentPath() {
    PlannedPath p = keeper.path();
    return p == null ? List.of() : p.toPoses();
  }

  /** The current path, or null. */
  public PlannedPath getPlannedPath() {
    return keeper.path();
  }

  /**
   * The area the local planner searched last cycle, as the corners of a rectangle (empty if none),
   * for display (ARNL's search rectangle).
   */
  public List<ArPose> getLocalSearchArea() {
    double[] a = keeper.searchArea();
    if (a == null) {
      return List.of();
    }
    return List.of(
        new ArPose(a[0], a[1]),
        new ArPose(a[2], a[1]),
        new ArPose(a[2], a[3]),
        new ArPose(a[0], a[3]));
  }

  /** The unmapped obstacle points the local planner avoided last cycle (a copy, for display). */
  public List<ArPose> getSensedObstacles() {
    return keeper.sensedPoses();
  }

  /** How long the last global plan took, ms. */
  public double getLastPlanMillis() {
    return keeper.lastPlanMillis();
  }

  /**
   * Replans made for the current (or last) goal: around newly seen obstacles, when the way was
   * blocked, or for lack of progress (only the last two count towards {@code MaxReplans}).
   */
  public int getReplanCount() {
    return keeper.replanCount();
  }

  // ================================================================ configuration

  /** Also avoid what {@code device} sees (bumpers, IRs, a forbidden-range device ...). */
  public void addRangeDevice(ArRangeDevice device, RangeType type) {
    keeper.sensed().addDevice(Objects.requireNonNull(device, "device"), type);
  }

  /** Stops using {@code device}. */
  public void remRangeDevice(ArRangeDevice device) {
    keeper.sensed().removeDevice(device);
  }

  /** The path-following action. */
  public ArActionPlanAndMoveToGoal getPathPlanAction() {
    return action;
  }

  /**
   * The action group of path following: add actions such as {@link ArActionLost} and {@link
   * ArActionSlowDownWhenNotCertain} to it, with priorities above 50.
   */
  public ArActionGroup getPathPlanActionGroup() {
    return group;
  }

  /** The parameters. */
  public PathPlanningParams getParams() {
    return params;
  }

  /** The config holding the parameters. */
  public ArConfig getConfig() {
    return params.getConfig();
  }

  /**
   * Loads parameters from an ARNL-style file ({@code Section Path planning} ...).
   *
   * @throws ArConfigException naming file and line if a value is bad (nothing is applied)
   */
  public ArConfig.ParseResult loadParamFile(Path file) throws ArConfigException, IOException {
    return params.getConfig().parseFile(file);
  }

  /** The map. */
  public ArMap getAriaMap() {
    return map;
  }

  /** The planning mode. */
  public PlanMode getPlanMode() {
    return mode;
  }

  // ================================================================ callbacks

  /** Runs with the goal when it is reached. */
  public void addGoalDoneCB(Consumer<ArPose> cb) {
    goalDoneCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a goal-done callback. */
  public void remGoalDoneCB(Consumer<ArPose> cb) {
    goalDoneCBs.remove(cb);
  }

  /** Runs with the goal when it fails (no plan, blocked, refused). */
  public void addGoalFailedCB(Consumer<ArPose> cb) {
    goalFailedCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a goal-failed callback. */
  public void remGoalFailedCB(Consumer<ArPose> cb) {
    goalFailedCBs.remove(cb);
  }

  /** Runs with the goal when it is cancelled or replaced. */
  public void addGoalInterruptedCB(Consumer<ArPose> cb) {
    goalInterruptedCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a goal-interrupted callback. */
  public void remGoalInterruptedCB(Consumer<ArPose> cb) {
    goalInterruptedCBs.remove(cb);
  }

  /** Runs with a new goal when it is given. */
  public void addNewGoalCB(Consumer<ArPose> cb) {
    newGoalCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a new-goal callback. */
  public void remNewGoalCB(Consumer<ArPose> cb) {
    newGoalCBs.remove(cb);
  }

  /** Runs when a goal ends in any way (done, failed, interrupted). */
  public void addGoalFinishedCB(Runnable cb) {
    goalFinishedCBs.add(Objects.requireNonNull(cb));
  }

  /** Removes a goal-finished callback. */
  public void remGoalFinishedCB(Runnable cb) {
    goalFinishedCBs.remove(cb);
  }

  // ================================================================ shutdown

  /** Cancels any goal, removes the action from the robot and stops the planning thread. */
  @Override
  public void close() {
    cancelPathPlan();
    group.removeActions();
    keeper.shutdown();
  }

  static double angleDiff(double a, double b) {
    return Math.abs(ArMath.subAngle(a, b));
  }
}
