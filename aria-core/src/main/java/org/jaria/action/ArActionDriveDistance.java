package org.jaria.action;

import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;

/**
 * Drives a given distance straight ahead (or back, for a negative distance) and stops (ARIA's
 * {@code ArActionDriveDistance}). The speed follows a braking profile: √(2 · deceleration ·
 * distance left), capped at the action's speed; the rotational velocity is held at 0. The distance
 * is counted from the odometry pose (or the corrected global pose) at {@link #setDistance}. The
 * goal is achieved once the distance is covered and the robot has stopped.
 *
 * <p>It does not avoid obstacles; add avoidance actions with higher priorities.
 */
public class ArActionDriveDistance extends ArAction {

  /** What the action is doing. */
  public enum State {
    /** No distance set, or cancelled. */
    STATE_NO_DISTANCE,
    /** The distance was covered. */
    STATE_ACHIEVED_DISTANCE,
    /** Driving. */
    STATE_GOING_DISTANCE
  }

  private final ArActionDesired desired = new ArActionDesired();
  private double speed;
  private double deceleration;
  private State state = State.STATE_NO_DISTANCE;
  private double distance;
  private boolean useEncoders;
  private ArPose lastPose = ArPose.ORIGIN;
  private double distTravelled;

  /** "driveDistance" with ARIA's defaults: 400 mm/s, 200 mm/s². */
  public ArActionDriveDistance() {
    this("driveDistance", 400, 200);
  }

  /**
   * A drive-distance action.
   *
   * @param name the action's name
   * @param speed top speed, mm/s
   * @param deceleration deceleration of the braking profile, mm/s²
   */
  public ArActionDriveDistance(String name, double speed, double deceleration) {
    super(name, "Drives a given distance.");
    this.speed = speed;
    this.deceleration = deceleration;
  }

  /** Whether the distance has been covered. */
  public boolean haveAchievedDistance() {
    return lockedGet(() -> state == State.STATE_ACHIEVED_DISTANCE);
  }

  /** Forgets the distance: the action asks for nothing. */
  public void cancelDistance() {
    locked(() -> state = State.STATE_NO_DISTANCE);
  }

  /** Drives {@code distance} mm (negative: backwards), counted with the odometry. */
  public void setDistance(double distance) {
    setDistance(distance, true);
  }

  /**
   * Drives {@code distance} mm (negative: backwards).
   *
   * @param useEncoders count with the odometry pose (true) or the corrected global pose
   * @throws IllegalStateException if the action has not been added to a robot
   */
  public void setDistance(double distance, boolean useEncoders) {
    locked(
        () -> {
          ArRobot robot = requireRobot();
          this.distance = distance;
          this.useEncoders = useEncoders;
          this.lastPose = useEncoders ? robot.getEncoderPose() : robot.getPose();
          this.distTravelled = 0;
          this.state = State.STATE_GOING_DISTANCE;
        });
  }

  /** Whether the distance is counted with the odometry pose. */
  public boolean usingEncoders() {
    return lockedGet(() -> useEncoders);
  }

  /** The state. */
  public State getState() {
    return lockedGet(() -> state);
  }

  /** Top speed, mm/s. */
  public double getSpeed() {
    return lockedGet(() -> speed);
  }

  /** Sets the top speed, mm/s (ARIA's default 400). */
  public void setSpeed(double speed) {
    locked(() -> this.speed = speed);
  }

  /** Deceleration of the braking profile, mm/s². */
  public double getDeceleration() {
    return lockedGet(() -> deceleration);
  }

  /** Sets the deceleration of the braking profile, mm/s² (ARIA's default 200). */
  public void setDeceleration(double deceleration) {
    locked(() -> this.deceleration = deceleration);
  }

  private ArRobot requireRobot() {
    ArRobot r = getRobot();
    if (r == null) {
      throw new IllegalStateException(
          "add the action to a robot (robot.addAction) before giving it a distance");
    }
    return r;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (state != State.STATE_GOING_DISTANCE) {
      return null;
    }
    ArRobot robot = getRobot();
    ArPose now = useEncoders ? robot.getEncoderPose() : robot.getPose();
    distTravelled += now.findDistanceTo(lastPose);
    lastPose = now;
    double distToGo = Math.abs(distance) - distTravelled;
    desired.reset();
    if (distToGo <= 0 && Math.abs(robot.getVel()) < 5) {
      state = State.STATE_ACHIEVED_DISTANCE;
      desired.setVel(0);
      desired.setRotVel(0);
      return desired;
    }
    desired.setRotVel(0);
    if (distToGo <= 0) {
      desired.setVel(0);
    } else {
      double vel = Math.min(Math.sqrt(distToGo * deceleration * 2), speed);
      desired.setVel(distance < 0 ? -vel : vel);
    }
    return desired;
  }
}
