package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * Limits the backward speed by what the range devices see behind (ARIA's {@code
 * ArActionLimiterBackwards}). Distances are negative, as in ARIA: the defaults stop at −250 mm and
 * slow from −600 mm, measured from the robot's edge. It looks in a box behind the robot's centre,
 * as wide as the robot times the width ratio. Nearer than the stop distance it sets the maximum
 * backward velocity to 0; between stop and slow distances it scales it from 0 to the maximum
 * backwards speed; otherwise it limits it to the maximum backwards speed.
 */
public class ArActionLimiterBackwards extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double stopDist;
  private volatile double slowDist;
  private volatile double maxBackwardsSpeed;
  private volatile double widthRatio;

  /** "speed limiter" with ARIA's defaults: stop −250 mm, slow −600 mm, −250 mm/s, ratio 1.5. */
  public ArActionLimiterBackwards() {
    this("speed limiter", -250, -600, -250, 1.5);
  }

  /**
   * A backward limiter.
   *
   * @param name the action's name
   * @param stopDistance distance at which to stop, mm (negative: behind)
   * @param slowDistance distance at which to start slowing, mm (negative)
   * @param maxBackwardsSpeed maximum backwards speed, mm/s (its sign is ignored)
   * @param widthRatio width of the checked box as a multiple of the robot's width
   */
  public ArActionLimiterBackwards(
      String name,
      double stopDistance,
      double slowDistance,
      double maxBackwardsSpeed,
      double widthRatio) {
    super(name, "Slows the robot down so as not to hit anything behind it.");
    this.stopDist = stopDistance;
    this.slowDist = slowDistance;
    this.maxBackwardsSpeed = maxBackwardsSpeed;
    this.widthRatio = widthRatio;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    double slowStopDist = Math.max(stopDist, slowDist);
    double halfWidth = robot.getRobotWidth() / 2.0 * widthRatio;
    desired.reset();
    // The box starts at the centre so that bumper readings, which lie inside the robot's
    // outline, are seen (ARIA does the same).
    double dist =
        RobotSensing.boxDistance(
                robot, 0, -halfWidth, slowStopDist - robot.getRobotLength(), halfWidth)
            - robot.getRobotRadius();
    double maxBack = -Math.abs(maxBackwardsSpeed);
    if (dist < -stopDist) {
      desired.setMaxNegVel(0);
    } else if (dist > -slowDist) {
      desired.setMaxNegVel(maxBack);
    } else {
      desired.setMaxNegVel(maxBack * ((-dist - stopDist) / (slowDist - stopDist)));
    }
    return desired;
  }
}
