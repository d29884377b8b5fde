package org.jaria.action;

import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;
import org.jaria.params.ArRobotParams;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Backs away and turns when a bumper is pressed (ARIA's {@code ArActionBumpers}). If the robot is
 * driving forward (faster than 25 mm/s) and a front bumper is hit, it backs up at the back-off
 * speed for the back-off time, then turns in place (for at most the turn time) away from the side
 * that was hit: the more central the bumper, the larger the turn, up to 67.5° (bumpers are spread
 * over a 135° arc). Driving backwards into a rear bumper, it drives forward and turns instead.
 * Which bumpers exist and how many segments they have come from the robot's parameters.
 *
 * <p>Bumper bits are read with {@link ArRobot#getFrontBumpers()} and {@link
 * ArRobot#getRearBumpers()}, so this action and {@link org.jaria.range.ArBumpers} always agree on
 * which ring is which.
 */
public class ArActionBumpers extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionBumpers.class);
  private static final double TURN_RANGE = 135;

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double backOffSpeed;
  private volatile int backOffTime;
  private volatile int turnTime;
  private volatile boolean setMaximums;
  private boolean firing;
  private double speed;
  private double heading;
  private long startBackNanos;

  /** "bumpers" with ARIA's defaults: 100 mm/s, back off 3000 ms, turn 3000 ms, no maximums. */
  public ArActionBumpers() {
    this("bumpers", 100, 3000, 3000, false);
  }

  /**
   * A bumpers action.
   *
   * @param name the action's name
   * @param backOffSpeed speed at which to back away, mm/s
   * @param backOffTime how long to back away, ms
   * @param turnTime how long to allow for the turn afterwards, ms
   * @param setMaximums also limit the maximum velocity to the back-off speed while backing away
   */
  public ArActionBumpers(
      String name, double backOffSpeed, int backOffTime, int turnTime, boolean setMaximums) {
    super(name, "Reacts to the bumpers triggering");
    this.backOffSpeed = backOffSpeed;
    this.backOffTime = backOffTime;
    this.turnTime = turnTime;
    this.setMaximums = setMaximums;
  }

  @Override
  public void activate() {
    locked(() -> firing = false);
    super.activate();
  }

  /**
   * How far to turn away after a bump, degrees: the pressed bumpers' mean position on the 135° arc
   * turned into a turn away from it (a bump on the left turns right, and the reverse).
   *
   * @param bumpValue bumper bits, bit 0 the first bumper (as {@link ArRobot#getFrontBumpers()})
   * @param whichBumper 1 for the front ring, 2 for the rear
   * @return the turn, degrees; 0 if none of the pressed bits is a fitted bumper
   */
  public double findDegreesToTurn(int bumpValue, int whichBumper) {
    ArRobotParams p = getRobot().getRobotParams();
    int numBumpers = whichBumper == 1 ? p.getNumFrontBumpers() : p.getNumRearBumpers();
    double total = 0;
    int numTurn = 0;
    double sector = TURN_RANGE / numBumpers;
    for (int i = 0; i < numBumpers && i < 8; i++) {
      if ((bumpValue & (1 << i)) != 0) {
        total += i * sector + sector / 2 - TURN_RANGE / 2;
        numTurn++;
      }
    }
    if (numTurn == 0) {
      // ARIA divided by zero here and turned to NaN.
      return 0;
    }
    total /= numTurn;
    return total < 0 ? -(TURN_RANGE / 2 + total) : TURN_RANGE / 2 - total;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    ArRobotParams p = robot.getRobotParams();
    int frontBump = p.haveFrontBumpers() ? robot.getFrontBumpers() : 0;
    int rearBump = p.haveRearBumpers() ? robot.getRearBumpers() : 0;
    long now = robot.getClock().nanoTime();
    desired.reset();
    if (firing) {
      long since = TimeUnit.NANOSECONDS.toMillis(now - startBackNanos);
      if (since < backOffTime) {
        if ((speed < 0 && rearBump != 0) || (speed > 0 && frontBump != 0)) {
          desired.setVel(0);
        } else {
          desired.setVel(speed);
        }
        desired.setDeltaHeading(0);
        return desired;
      } else if (since < (long) backOffTime + turnTime
          && Math.abs(ArMath.subAngle(robot.getTh(), heading)) > 3) {
        desired.setVel(0);
        desired.setHeading(heading);
        return desired;
      }
      firing = false;
      log.info("Bumpers: done");
    }

    double vel = robot.getVel();
    if (vel > 25) {
      if (frontBump == 0) {
        return null;
      }
      double turn = findDegreesToTurn(frontBump, 1);
      log.info("Bumpers: bumped a front bumper while going forward, turning {}", turn);
      heading = ArMath.addAngle(robot.getTh(), turn);
      speed = -backOffSpeed;
    } else if (vel < -25) {
      if (rearBump == 0) {
        return null;
      }
      double turn = findDegreesToTurn(rearBump, 2);
      log.info("Bumpers: bumped a rear bumper while going backwards, turning {}", turn);
      heading = ArMath.subAngle(robot.getTh(), turn);
      speed = backOffSpeed;
    } else {
      return null;
    }
    startBackNanos = now;
    firing = true;
    desired.setVel(speed);
    desired.setHeading(heading);
    if (setMaximums) {
      if (speed > 0) {
        desired.setMaxVel(speed);
      } else {
        desired.setMaxNegVel(speed);
      }
    }
    return desired;
  }
}
