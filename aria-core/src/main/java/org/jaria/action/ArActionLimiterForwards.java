package org.jaria.action;

import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Limits the forward speed by what the range devices see ahead (ARIA's {@code
 * ArActionLimiterForwards}). It looks in a box in front of the robot, as wide as the robot times
 * the width ratio, reaching the slow distance past the robot's front. If the closest reading is
 * nearer than the stop distance (from the front), it sets the maximum velocity to 0; between the
 * stop and slow distances the maximum grows linearly from 0 to the slow speed; farther away it asks
 * for nothing. It only sets the maximum-velocity channel, so put it above the actions that drive.
 */
public class ArActionLimiterForwards extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionLimiterForwards.class);

  private final ArActionDesired desired = new ArActionDesired();
  private double stopDist;
  private double slowDist;
  private double slowSpeed;
  private double widthRatio;
  private boolean lastStopped;

  /** "speed limiter" with ARIA's defaults: stop 250 mm, slow 1000 mm, 200 mm/s, width ratio 1. */
  public ArActionLimiterForwards() {
    this("speed limiter");
  }

  /** A forward limiter with ARIA's default distances and this name. */
  public ArActionLimiterForwards(String name) {
    this(name, 250, 1000, 200, 1);
  }

  /** A forward limiter with width ratio 1. */
  public ArActionLimiterForwards(
      String name, double stopDistance, double slowDistance, double slowSpeed) {
    this(name, stopDistance, slowDistance, slowSpeed, 1);
  }

  /**
   * A forward limiter.
   *
   * @param name the action's name
   * @param stopDistance distance from the robot's front at which to stop, mm
   * @param slowDistance distance from the front at which to start slowing, mm
   * @param slowSpeed maximum speed allowed at the slow distance, mm/s
   * @param widthRatio width of the checked box as a multiple of the robot's width
   */
  public ArActionLimiterForwards(
      String name, double stopDistance, double slowDistance, double slowSpeed, double widthRatio) {
    super(name, "Slows the robot down so as not to hit anything in front of it.");
    setParameters(stopDistance, slowDistance, slowSpeed, widthRatio);
  }

  /** Sets the parameters, as the constructor (ARIA's defaults: 250, 1000, 200, 1). */
  public void setParameters(
      double stopDistance, double slowDistance, double slowSpeed, double widthRatio) {
    locked(
        () -> {
          this.stopDist = stopDistance;
          this.slowDist = slowDistance;
          this.slowSpeed = slowSpeed;
          this.widthRatio = widthRatio;
        });
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    double checkDist = Math.max(stopDist, slowDist);
    double halfWidth = robot.getRobotWidth() / 2.0 * widthRatio;
    double front = robot.getRobotLength() / 2;
    desired.reset();
    double dist =
        RobotSensing.boxDistance(robot, 0, -halfWidth, checkDist + front, halfWidth) - front;
    if (dist < stopDist) {
      if (!lastStopped) {
        log.debug("{}: stopping due to a sensor reading", getName());
      }
      lastStopped = true;
      desired.setMaxVel(0);
      return desired;
    }
    if (lastStopped) {
      log.debug("{}: allowing motion", getName());
    }
    lastStopped = false;
    if (dist > slowDist) {
      return null;
    }
    desired.setMaxVel(slowSpeed * ((dist - stopDist) / (slowDist - stopDist)));
    return desired;
  }
}
