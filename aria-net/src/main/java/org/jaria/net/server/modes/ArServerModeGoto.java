package org.jaria.net.server.modes;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArActionGoto;
import org.jaria.action.ArActionGroup;
import org.jaria.action.ArActionStallRecover;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.net.ArNetPacket;
import org.jaria.net.protocol.NetError;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ArServerClient;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.NumericArgs;
import org.jaria.net.server.TextLimits;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Drives to a pose or a named map goal (ArNetworking's {@code ArServerModeGoto}).
 *
 * <p>With a {@link PathPlanningInfo} (SonARNL's path planner through an adapter) the mode hands the
 * goal to the planner, which plans round the map's walls and drives. Without one it drives straight
 * with ARIA's actions, as the thesis's gotoActionExample: {@link ArActionGoto} under stall
 * recovery, bumpers and two front avoiders, then, at the goal, turns to the goal's heading if
 * asked. Client requests: {@code "gotoPose"} (x, y[, th, useHeading]), {@code "gotoGoal"} (name),
 * {@code "getGoals"}.
 */
public class ArServerModeGoto extends ArServerMode {

  /** Longest wait of a goal request for the robot's cycle to switch to this mode. */
  private static final long ACTIVATION_TIMEOUT_SECONDS = 5;

  private final PathPlanningInfo planner;
  private volatile ArMap map;
  private final ArActionGroup group;
  private final ArActionGoto gotoAction = new ArActionGoto("goto");
  private final HoldAtGoal hold = new HoldAtGoal(gotoAction);
  // Cycle thread only.
  private String goalName = "";

  /** A goto mode that drives straight with actions (no planner). */
  public ArServerModeGoto(ArServerBase server, ArRobot robot, ArMap map) {
    this(server, robot, null, map);
  }

  /**
   * A goto mode.
   *
   * @param planner the path planner to delegate to, or null to drive straight with actions
   * @param map the map whose goals can be named (null: only poses)
   */
  public ArServerModeGoto(ArServerBase server, ArRobot robot, PathPlanningInfo planner, ArMap map) {
    super(server, robot, "Goto");
    this.planner = planner;
    this.map = map;
    group = new ArActionGroup(robot);
    withRobotLocked(
        robot,
        () -> {
          gotoAction.cancelGoal();
          group.addAction(new ArActionStallRecover(), 100);
          group.addAction(new ArActionBumpers(), 75);
          group.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0), 50);
          group.addAction(new ArActionAvoidFront(), 49);
          group.addAction(gotoAction, 40);
          group.addAction(hold, 30);
          group.deactivate();
        });
    Where where = planner == null ? Where.CYCLE : Where.WORKER;
    server.addData(
        "gotoPose",
        "drives to a pose",
        "byte4: x; byte4: y; (optional) byte2: th",
        "none",
        "Movement",
        where,
        this::serverGotoPose);
    server.addData(
        "gotoGoal",
        "drives to a goal of the map",
        "string goal name",
        "none",
        "Movement",
        where,
        this::serverGotoGoal);
    server.addData(
        "getGoals",
        "the names of the map's goals",
        "none",
        "array of string",
        "RobotInfo",
        Where.WORKER,
        (client, request, reply) -> {
          // ArNetworking's layout: one string per goal, to the end of the packet.
          for (String g : getGoals()) {
            if (reply.getWriteCapacity() < g.length() * 3 + 1) {
              break;
            }
            reply.strToBuf(g);
          }
        });
  }

  /**
   * Registers ARNL's {@code "home"}: drive to the map's home (its first RobotHome, else its first
   * Dock), as a goal with heading. Separate from the constructor so that a server can add it after
   * its other data. Without a home on the map the request fails with a message saying so.
   */
  public void addHomeRequest() {
    server.addData(
        "home",
        "Activate Goal mode and send the robot to the Home point in the map (if any)",
        "none",
        "none",
        "Movement",
        planner == null ? Where.CYCLE : Where.WORKER,
        (client, request, reply) -> {
          ArMap m = map;
          ArPose home =
              m == null
                  ? null
                  : m.findFirstMapObjectOfType("RobotHome")
                      .or(() -> m.findFirstMapObjectOfType("Dock"))
                      .map(ArMapObject::pose)
                      .orElse(null);
          if (home == null) {
            throw new NetRequestException(
                NetError.UNAVAILABLE, "the map has no RobotHome (or Dock) to return to");
          }
          if (planner != null) {
            startWithPlanner("home", () -> planner.pathPlanToPose(home, true));
          } else {
            gotoPose(home, true, "home");
          }
        });
  }

  /**
   * Takes goals and bounds from another map from now on (after a map change; a goal being driven to
   * is cancelled by stopping first).
   */
  public void setMap(ArMap m) {
    map = m;
  }

  /** The names of the map's goals, in map order. */
  public List<String> getGoals() {
    List<String> l = new ArrayList<>();
    ArMap m = map;
    if (m != null) {
      for (ArMapObject o : m.getGoals()) {
        l.add(o.name());
      }
    }
    return l;
  }

  /** The goto actions used without a planner (to add, say, an ArActionLost). */
  public ArActionGroup getActionGroup() {
    return group;
  }

  private void serverGotoPose(ArServerClient client, ArNetPacket request, ArNetPacket reply)
      throws NetRequestException, InterruptedException {
    // ArNetworking's gotoPose: byte4 x, byte4 y and, optionally, byte2 th (then the heading is
    // used).
    double x = request.bufToByte4();
    double y = request.bufToByte4();
    boolean useHeading = request.hasMore();
    double th = useHeading ? request.bufToByte2() : 0;
    ArPose goal = NumericArgs.pose(x, y, th, map);
    String name = String.format(Locale.ROOT, "pose (%.0f, %.0f)", x, y);
    if (planner != null) {
      startWithPlanner(name, () -> planner.pathPlanToPose(goal, useHeading));
    } else {
      gotoPose(goal, useHeading, name);
    }
  }

  private void serverGotoGoal(ArServerClient client, ArNetPacket request, ArNetPacket reply)
      throws NetRequestException, InterruptedException {
    String name = request.bufToStr();
    if (name.length() > TextLimits.MAX_NAME) {
      throw new NetRequestException(
          NetError.BAD_ARGUMENTS,
          "a goal name has at most " + TextLimits.MAX_NAME + " characters; see getGoals");
    }
    if (planner != null) {
      startWithPlanner("goal " + name, () -> planner.pathPlanToGoal(name));
      return;
    }
    ArMap m = map;
    Optional<ArMapObject> goal =
        m == null
            ? Optional.empty()
            : m.getGoals().stream().filter(o -> o.name().equalsIgnoreCase(name)).findFirst();
    if (goal.isEmpty()) {
      throw new NetRequestException(
          NetError.BAD_ARGUMENTS, "no goal called '" + name + "' on the map; see getGoals");
    }
    gotoPose(goal.get().pose(), goal.get().type().equals("GoalWithHeading"), "goal " + name);
  }

  private interface PlanStart {
    boolean start();
  }

  /**
   * Worker thread: switches to this mode on the robot's cycle and waits for that, then hands the
   * goal to the planner. Waiting keeps the order of requests: a "stop" sent before this goal
   * cancels the old goal, never the new one.
   */
  private void startWithPlanner(String name, PlanStart start)
      throws NetRequestException, InterruptedException {
    CompletableFuture<Void> active = new CompletableFuture<>();
    if (!server.runOnCycle(
        () -> {
          activate();
          goalName = name;
          setStatus("Planning a path to " + name);
          active.complete(null);
        })) {
      throw new NetRequestException(NetError.BUSY, "the robot's command queue is full");
    }
    try {
      active.get(ACTIVATION_TIMEOUT_SECONDS, TimeUnit.SECONDS);
    } catch (TimeoutException | ExecutionException e) {
      throw new NetRequestException(
          NetError.FAILED,
          "the robot's cycle did not switch to goto within "
              + ACTIVATION_TIMEOUT_SECONDS
              + " s: is the robot connected and running?");
    }
    if (!start.start()) {
      throw new NetRequestException(
          NetError.FAILED, "cannot go to " + name + ": " + planner.getStatusString());
    }
    if (!isActive()) {
      // A stop (or another mode) took over while the plan was being started: deactivating this
      // mode cancelled the plan before it existed, so cancel the one just started.
      planner.cancelPathPlan();
      throw new NetRequestException(
          NetError.FAILED, "the goal to " + name + " was cancelled by a newer command");
    }
  }

  /**
   * Drives to {@code goal} with the straight-line actions (cycle thread), activating the mode.
   *
   * @param useHeading turn to the goal's heading at the end
   * @param name how the status names the goal
   */
  public void gotoPose(ArPose goal, boolean useHeading, String name) {
    activate();
    goalName = name;
    hold.set(goal.getTh(), useHeading);
    gotoAction.setGoal(goal);
    setStatus("Going to " + name);
  }

  @Override
  protected void onActivate() {
    robot.clearDirectMotion();
    robot.enableMotors();
    if (planner == null) {
      gotoAction.cancelGoal();
      group.activateExclusive();
    } else {
      planner.getActionGroup().activateExclusive();
    }
    setStatus("Waiting for a goal");
  }

  @Override
  protected void onDeactivate() {
    if (planner != null) {
      planner.cancelPathPlan();
      planner.getActionGroup().deactivate();
    } else {
      gotoAction.cancelGoal();
      group.deactivate();
    }
  }

  @Override
  protected void userTask() {
    if (planner != null) {
      String status = planner.getStatusString();
      if (status != null && !status.isEmpty()) {
        setStatus(status);
      }
      return;
    }
    if (gotoAction.haveAchievedGoal()) {
      setStatus(hold.turned(robot.getTh()) ? "Arrived at " + goalName : "Turning at " + goalName);
    }
  }

  /** At the goal: stand still, turning to the goal's heading if asked. */
  private static final class HoldAtGoal extends ArAction {
    private final ArActionDesired desired = new ArActionDesired();
    private final ArActionGoto gotoAction;
    private volatile double heading;
    private volatile boolean useHeading;

    HoldAtGoal(ArActionGoto gotoAction) {
      super("Hold at goal", "stands still at the goal, facing its heading if asked");
      this.gotoAction = gotoAction;
    }

    void set(double th, boolean use) {
      heading = th;
      useHeading = use;
    }

    boolean turned(double th) {
      return !useHeading || Math.abs(ArMath.subAngle(heading, th)) < 3;
    }

    @Override
    public ArActionDesired fire(ArActionDesired currentDesired) {
      if (!gotoAction.haveAchievedGoal()) {
        return null;
      }
      desired.reset();
      desired.setVel(0);
      if (useHeading) {
        desired.setHeading(heading);
      } else {
        desired.setRotVel(0);
      }
      return desired;
    }
  }
}
