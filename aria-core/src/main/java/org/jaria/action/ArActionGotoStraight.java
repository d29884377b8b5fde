package org.jaria.action;

import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Drives straight to a goal position, turning and driving at the same time (ARIA's {@code
 * ArActionGotoStraight}). The speed brakes as the goal nears (√(2 · 200 · distance), capped at the
 * action's speed). Goals may be given in global coordinates ({@link #setGoal}), in odometry
 * coordinates ({@link #setEncoderGoal}, which stays put when localization moves the robot's global
 * pose), or relative to the robot ({@link #setGoalRel}, {@link #setEncoderGoalRel}); with {@code
 * backwards} the robot reverses to the goal.
 *
 * <p>In "just distance" mode (the default) the goal counts as reached once the robot has travelled
 * the distance it was from the goal when it was set; otherwise once it is within the close
 * distance. Either way it must also have stopped. With a turn threshold set, the robot turns in
 * place before driving whenever the goal is further off its heading than the threshold.
 *
 * <p>It does not avoid obstacles; add avoidance actions with higher priorities.
 *
 * <p>Differences from ARIA: ARIA compared the heading of the (odometry) pose with a global
 * direction to decide whether to turn in place, which is wrong for encoder goals once the robot has
 * been relocalized; here the robot's global heading is used. ARIA also kept the previous cycle's
 * desire, so a turn-speed limit could outlive the turn; here each cycle starts afresh.
 */
public class ArActionGotoStraight extends ArAction {

  /** What the action is doing. */
  public enum State {
    /** No goal, or cancelled. */
    STATE_NO_GOAL,
    /** The goal was reached. */
    STATE_ACHIEVED_GOAL,
    /** Driving to the goal. */
    STATE_GOING_TO_GOAL
  }

  private static final Logger log = LoggerFactory.getLogger(ArActionGotoStraight.class);

  private final ArActionDesired desired = new ArActionDesired();
  private ArPose goal = ArPose.ORIGIN;
  private ArPose encoderGoal = ArPose.ORIGIN;
  private boolean useEncoderGoal;
  private double speed;
  private boolean backing;
  private double dist;
  private double closeDist = 100;
  private boolean justDist = true;
  private double distTravelled;
  private ArPose lastPose = ArPose.ORIGIN;
  private double turnThresh = 360;
  private double maxTurnSpeed;
  private double maxRotVel;
  private State state = State.STATE_NO_GOAL;

  /** "goto" at ARIA's default 400 mm/s. */
  public ArActionGotoStraight() {
    this("goto", 400);
  }

  /** A goto-straight action with a top speed, mm/s. */
  public ArActionGotoStraight(String name, double speed) {
    super(name, "Goes to the given goal.");
    this.speed = speed;
  }

  /** Whether the goal has been reached. */
  public boolean haveAchievedGoal() {
    return lockedGet(() -> state == State.STATE_ACHIEVED_GOAL);
  }

  /** Forgets the goal: the action asks for nothing. */
  public void cancelGoal() {
    locked(() -> state = State.STATE_NO_GOAL);
  }

  /** Drives forwards to a global goal, in just-distance mode. */
  public void setGoal(ArPose goal) {
    setGoal(goal, false, true);
  }

  /**
   * Drives to a goal in global coordinates.
   *
   * @param goal the goal
   * @param backwards reverse to it
   * @param justDistance stop after covering the distance to it (else: when within the close
   *     distance)
   * @throws IllegalStateException if the action has not been added to a robot
   */
  public void setGoal(ArPose goal, boolean backwards, boolean justDistance) {
    locked(
        () -> {
          ArRobot robot = requireRobot();
          this.goal = goal;
          this.useEncoderGoal = false;
          this.backing = backwards;
          this.lastPose = robot.getPose();
          this.dist = lastPose.findDistanceTo(goal);
          this.justDist = justDistance;
          this.distTravelled = 0;
          this.state = State.STATE_GOING_TO_GOAL;
        });
  }

  /** Drives to a goal {@code dist} mm away in the direction {@code deltaHeading} from the robot. */
  public void setGoalRel(double dist, double deltaHeading) {
    setGoalRel(dist, deltaHeading, false, true);
  }

  /**
   * Drives to a goal {@code dist} mm away, {@code deltaHeading} degrees off the robot's heading
   * (taken now, in global coordinates).
   */
  public void setGoalRel(
      double dist, double deltaHeading, boolean backwards, boolean justDistance) {
    locked(() -> setGoal(relativeGoal(dist, deltaHeading), backwards, justDistance));
  }

  /** Drives forwards to a goal in odometry coordinates, in just-distance mode. */
  public void setEncoderGoal(ArPose encoderGoal) {
    setEncoderGoal(encoderGoal, false, true);
  }

  /**
   * Drives to a goal in odometry coordinates: it stays where it is on the floor when localization
   * corrects the robot's global pose.
   */
  public void setEncoderGoal(ArPose encoderGoal, boolean backwards, boolean justDistance) {
    locked(
        () -> {
          ArRobot robot = requireRobot();
          this.encoderGoal = encoderGoal;
          this.useEncoderGoal = true;
          this.backing = backwards;
          this.lastPose = robot.getEncoderPose();
          this.dist = lastPose.findDistanceTo(encoderGoal);
          this.justDist = justDistance;
          this.distTravelled = 0;
          this.state = State.STATE_GOING_TO_GOAL;
        });
  }

  /** As {@link #setGoalRel}, but the goal is kept in odometry coordinates. */
  public void setEncoderGoalRel(
      double dist, double deltaHeading, boolean backwards, boolean justDistance) {
    locked(
        () -> {
          ArPose global = relativeGoal(dist, deltaHeading);
          setEncoderGoal(
              requireRobot().getEncoderTransform().inverse().doTransform(global),
              backwards,
              justDistance);
        });
  }

  private ArPose relativeGoal(double dist, double deltaHeading) {
    double r = Math.toRadians(deltaHeading);
    return requireRobot()
        .getToGlobalTransform()
        .doTransform(new ArPose(dist * Math.cos(r), dist * Math.sin(r)));
  }

  private ArRobot requireRobot() {
    ArRobot r = getRobot();
    if (r == null) {
      throw new IllegalStateException(
          "add the action to a robot (robot.addAction) before giving it a goal");
    }
    return r;
  }

  /** The global goal. */
  public ArPose getGoal() {
    return lockedGet(() -> goal);
  }

  /** The odometry goal. */
  public ArPose getEncoderGoal() {
    return lockedGet(() -> encoderGoal);
  }

  /** Whether the goal is in odometry coordinates. */
  public boolean usingEncoderGoal() {
    return lockedGet(() -> useEncoderGoal);
  }

  /** Whether the robot reverses to the goal. */
  public boolean getBacking() {
    return lockedGet(() -> backing);
  }

  /** The state. */
  public State getState() {
    return lockedGet(() -> state);
  }

  /** Top speed, mm/s. */
  public double getSpeed() {
    return lockedGet(() -> speed);
  }

  /** Sets the top speed, mm/s. */
  public void setSpeed(double speed) {
    locked(() -> this.speed = speed);
  }

  /** How close counts as arrived when not in just-distance mode, mm (default 100). */
  public double getCloseDist() {
    return lockedGet(() -> closeDist);
  }

  /** Sets how close counts as arrived when not in just-distance mode, mm. */
  public void setCloseDist(double closeDist) {
    locked(() -> this.closeDist = closeDist);
  }

  /**
   * Turns in place, without driving, while the goal is more than {@code threshAngle} degrees off
   * the heading (default 360: never). Below about 20° the robot may never get there.
   */
  public void setTurnThreshold(double threshAngle) {
    locked(() -> turnThresh = threshAngle);
  }

  /** Maximum rotational velocity while turning in place, deg/s (0: the robot's). */
  public void setTurnSpeed(double degPerSec) {
    locked(() -> maxTurnSpeed = degPerSec);
  }

  /** Maximum rotational velocity while driving, deg/s (0: the robot's). */
  public void setMaxRotVel(double degPerSec) {
    locked(() -> maxRotVel = degPerSec);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (state != State.STATE_GOING_TO_GOAL) {
      return null;
    }
    ArRobot robot = getRobot();
    ArPose target;
    if (useEncoderGoal) {
      target = robot.getEncoderTransform().doTransform(encoderGoal);
      ArPose now = robot.getEncoderPose();
      distTravelled += now.findDistanceTo(lastPose);
      lastPose = now;
    } else {
      target = goal;
      ArPose now = robot.getPose();
      distTravelled += now.findDistanceTo(lastPose);
      lastPose = now;
    }
    ArPose pose = robot.getPose();
    double distToGo = 0;
    double d;
    if (justDist) {
      distToGo = dist - distTravelled;
      d = Math.abs(distToGo);
    } else {
      d = pose.findDistanceTo(target);
    }
    boolean there = justDist ? distToGo <= 0 : d < closeDist;
    desired.reset();
    if (there && Math.abs(robot.getVel()) < 5) {
      log.info("{}: achieved goal (distance left {})", getName(), justDist ? distToGo : d);
      state = State.STATE_ACHIEVED_GOAL;
      desired.setVel(0);
      desired.setDeltaHeading(0);
      return desired;
    }
    double angle = pose.findAngleTo(target);
    if (backing) {
      angle = ArMath.subAngle(angle, 180);
    }
    desired.setHeading(angle);
    double angleDelta = ArMath.subAngle(robot.getTh(), angle);
    if (there) {
      desired.setVel(0);
    } else if (Math.abs(angleDelta) <= turnThresh) {
      double vel = Math.min(Math.sqrt(d * 200 * 2), speed);
      desired.setVel(backing ? -vel : vel);
      if (maxRotVel > 1e-9) {
        desired.setMaxRotVel(maxRotVel);
      }
    } else if (maxTurnSpeed > 1e-9) {
      desired.setMaxRotVel(maxTurnSpeed);
    }
    return desired;
  }
}
