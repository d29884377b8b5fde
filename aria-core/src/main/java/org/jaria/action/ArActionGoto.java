package org.jaria.action;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;

/**
 * Drives to a goal position (ARIA's {@code ArActionGoto}). It points the robot at the goal and
 * drives at a speed that brakes as it nears (√(2 · 200 · distance), capped at the action's speed),
 * stopping within the close distance; the goal is achieved once the robot is that close and has
 * stopped. If a higher-priority action has limited the speed below the speed-to-turn-at (an
 * obstacle ahead), it turns by the turn amount instead of pointing at the goal, so simple avoidance
 * actions can lead it round obstacles. The goal's heading is ignored.
 *
 * <p>Besides ARIA's {@link #setGoal}, a route can be given with {@link #setGoals}: the action
 * drives to each pose in turn and {@link #haveAchievedGoal()} becomes true at the last one.
 */
public class ArActionGoto extends ArAction {

  /** What the action is doing. */
  public enum State {
    /** No goal, or cancelled. */
    STATE_NO_GOAL,
    /** The goal was reached. */
    STATE_ACHIEVED_GOAL,
    /** Driving to the goal. */
    STATE_GOING_TO_GOAL
  }

  private final ArActionDesired desired = new ArActionDesired();
  private final List<ArPose> route = new ArrayList<>();
  private ArPose goal;
  private double closeDist;
  private double speed;
  private double speedToTurnAt;
  private double turnAmount;
  private State state = State.STATE_NO_GOAL;
  private double directionToTurn = 1;
  private double curTurnDir = 1;
  private int routeIndex;

  /**
   * "goto" with ARIA's defaults: goal (0, 0), 100 mm close, 400 mm/s, turn below 150 mm/s by 7°. As
   * in ARIA the action starts out driving to the origin; give it a goal before adding it.
   */
  public ArActionGoto() {
    this("goto");
  }

  /** An action with ARIA's default parameters (goal at the origin) and this name. */
  public ArActionGoto(String name) {
    this(name, ArPose.ORIGIN, 100, 400, 150, 7);
  }

  /**
   * A goto action, driving to {@code goal} at once.
   *
   * @param name the action's name
   * @param goal where to go
   * @param closeDist how close counts as arrived, mm
   * @param speed top speed, mm/s
   * @param speedToTurnAt below this maximum velocity (set by higher priorities) turn to avoid, mm/s
   * @param turnAmount degrees to turn per cycle when avoiding
   */
  public ArActionGoto(
      String name,
      ArPose goal,
      double closeDist,
      double speed,
      double speedToTurnAt,
      double turnAmount) {
    super(name, "Goes to the given goal.");
    this.closeDist = closeDist;
    this.speed = speed;
    this.speedToTurnAt = speedToTurnAt;
    this.turnAmount = turnAmount;
    setGoal(goal);
  }

  /** Whether the goal (the last goal of a route) has been reached. */
  public boolean haveAchievedGoal() {
    return lockedGet(() -> state == State.STATE_ACHIEVED_GOAL);
  }

  /** Forgets the goal (and any route): the action asks for nothing. */
  public void cancelGoal() {
    locked(
        () -> {
          state = State.STATE_NO_GOAL;
          route.clear();
        });
  }

  /** Sets a new goal and drives there (any route is forgotten). */
  public void setGoal(ArPose newGoal) {
    locked(
        () -> {
          route.clear();
          startGoal(newGoal);
        });
  }

  private void startGoal(ArPose newGoal) {
    goal = newGoal;
    state = State.STATE_GOING_TO_GOAL;
    curTurnDir = directionToTurn;
  }

  /**
   * Drives through {@code goals} in order; {@link #haveAchievedGoal()} becomes true at the last. An
   * empty list cancels the goal.
   */
  public void setGoals(List<ArPose> goals) {
    locked(
        () -> {
          route.clear();
          route.addAll(goals);
          routeIndex = 0;
          if (route.isEmpty()) {
            state = State.STATE_NO_GOAL;
          } else {
            startGoal(route.get(0));
          }
        });
  }

  /** Index in the route of the goal being driven to (0 when a single goal was set). */
  public int getGoalIndex() {
    return lockedGet(() -> routeIndex);
  }

  /** The goal being driven to (or last driven to). */
  public ArPose getGoal() {
    return lockedGet(() -> goal);
  }

  /** The state. */
  public State getState() {
    return lockedGet(() -> state);
  }

  /** How close counts as arrived, mm. */
  public double getCloseDist() {
    return lockedGet(() -> closeDist);
  }

  /** Sets how close counts as arrived, mm. */
  public void setCloseDist(double closeDist) {
    locked(() -> this.closeDist = closeDist);
  }

  /** Top speed, mm/s. */
  public double getSpeed() {
    return lockedGet(() -> speed);
  }

  /** Sets the top speed, mm/s. */
  public void setSpeed(double speed) {
    locked(() -> this.speed = speed);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (state != State.STATE_GOING_TO_GOAL) {
      return null;
    }
    ArRobot robot = getRobot();
    ArPose pose = robot.getPose();
    double dist = pose.findDistanceTo(goal);
    desired.reset();
    if (dist < closeDist && Math.abs(robot.getVel()) < 5) {
      arrived();
      desired.setVel(0);
      desired.setDeltaHeading(0);
      return desired;
    }
    double angle = pose.findAngleTo(goal);
    if (Math.abs(ArMath.subAngle(angle, robot.getTh())) > 120) {
      curTurnDir *= -1;
    }
    if (currentDesired.getMaxVelStrength() > 0 && currentDesired.getMaxVel() < speedToTurnAt) {
      // Something ahead is slowing us down: turn away.
      desired.setDeltaHeading(turnAmount * curTurnDir);
    } else if (Math.abs(
            ArMath.subAngle(angle, ArMath.addAngle(-turnAmount * curTurnDir, robot.getTh())))
        > turnAmount / 2) {
      desired.setHeading(angle);
    } else {
      desired.setDeltaHeading(-turnAmount * curTurnDir);
    }
    if (dist < closeDist) {
      desired.setVel(0);
    } else {
      desired.setVel(Math.min(Math.sqrt(dist * 200 * 2), speed));
    }
    return desired;
  }

  private void arrived() {
    if (!route.isEmpty() && routeIndex + 1 < route.size()) {
      routeIndex++;
      startGoal(route.get(routeIndex));
    } else {
      state = State.STATE_ACHIEVED_GOAL;
    }
  }
}
