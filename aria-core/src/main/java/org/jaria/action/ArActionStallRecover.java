package org.jaria.action;

import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Gets the robot out of a stall (ARIA's {@code ArActionStallRecover}). When a wheel motor stalls
 * (pushing against something), it takes over translation and rotation for a while: it backs up or
 * drives forward at its speed for a number of cycles (halving them if an obstacle is within the
 * obstacle distance), turns by the degrees to turn, or both. Stalls in quick succession (within 5
 * seconds) try the next manoeuvre of a fixed sequence: back and turn, forward and turn, back,
 * forward, turn left, turn right, back and left, back and right, forward and left, forward and
 * right. When turning it chooses the side away from the stalled wheel, or the more open side.
 *
 * <p>If a higher-priority action already uses the velocity or heading at full strength, the
 * manoeuvre is abandoned. Put it at the top of the priority list (the thesis's obstacle-avoidance
 * example uses priority 100).
 */
public class ArActionStallRecover extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionStallRecover.class);

  private static final int BACK = 0x1;
  private static final int FORWARD = 0x2;
  private static final int TURN = 0x4;
  private static final int TURN_LEFT = 0x8;
  private static final int TURN_RIGHT = 0x10;
  private static final int MOVEMASK = BACK | FORWARD;
  private static final int TURNMASK = TURN | TURN_LEFT | TURN_RIGHT;
  private static final int[] SEQUENCE = {
    BACK | TURN,
    FORWARD | TURN,
    BACK,
    FORWARD,
    TURN_LEFT,
    TURN_RIGHT,
    BACK | TURN_LEFT,
    BACK | TURN_RIGHT,
    FORWARD | TURN_LEFT,
    FORWARD | TURN_RIGHT
  };

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double obstacleDistance;
  private volatile int cyclesToMove;
  private volatile double speed;
  private volatile double degreesToTurn;
  private volatile boolean enabled;
  private boolean going;
  private int count = -1;
  private int sequencePos;
  private int doing;
  private int sideStalled;
  private double desiredHeading;
  private long lastFiredNanos = Long.MIN_VALUE / 2;

  /** "stall recover" with ARIA's defaults: 225 mm, 50 cycles, 150 mm/s, 45°. */
  public ArActionStallRecover() {
    this("stall recover", 225, 50, 150, 45, true);
  }

  /** A stall-recover action, enabled. */
  public ArActionStallRecover(
      String name, double obstacleDistance, int cyclesToMove, double speed, double degreesToTurn) {
    this(name, obstacleDistance, cyclesToMove, speed, degreesToTurn, true);
  }

  /**
   * A stall-recover action.
   *
   * @param name the action's name
   * @param obstacleDistance distance from the robot's edge at which not to keep moving, mm
   * @param cyclesToMove how many cycles a manoeuvre lasts
   * @param speed speed to back up or drive forward at, mm/s
   * @param degreesToTurn how far to turn, degrees
   * @param enabled whether it reacts to stalls at all
   */
  public ArActionStallRecover(
      String name,
      double obstacleDistance,
      int cyclesToMove,
      double speed,
      double degreesToTurn,
      boolean enabled) {
    super(name, "Recovers the robot from a stall.");
    this.obstacleDistance = obstacleDistance;
    this.cyclesToMove = cyclesToMove;
    this.speed = speed;
    this.degreesToTurn = degreesToTurn;
    this.enabled = enabled;
  }

  @Override
  public void activate() {
    locked(() -> going = false);
    super.activate();
  }

  /** Whether the action reacts to stalls. */
  public boolean isEnabled() {
    return enabled;
  }

  /** Sets whether the action reacts to stalls. */
  public void setEnabled(boolean enabled) {
    this.enabled = enabled;
  }

  /** Whether a recovery manoeuvre is under way. */
  public boolean isRecovering() {
    return lockedGet(() -> going);
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    if (!enabled) {
      return null;
    }
    ArRobot robot = getRobot();
    if (currentDesired.getVelStrength() >= 1.0
        || currentDesired.getDeltaHeadingStrength() >= 1.0
        || currentDesired.getHeadingStrength() >= 1.0
        || currentDesired.getRotVelStrength() >= 1.0) {
      if (going) {
        going = false;
        count = -1;
        log.info("StallRecover: done (interrupted)");
      }
      return null;
    }
    desired.reset();
    long now = robot.getClock().nanoTime();
    if (!going) {
      boolean left = robot.isLeftMotorStalled();
      boolean right = robot.isRightMotorStalled();
      if (!left && !right) {
        return null;
      }
      if (now - lastFiredNanos <= TimeUnit.SECONDS.toNanos(5)) {
        sequencePos++;
      } else {
        sequencePos = 0;
      }
      if (sequencePos >= SEQUENCE.length) {
        sequencePos = 0;
      }
      doing = SEQUENCE[sequencePos];
      log.info(
          "StallRecover: {} stalled, doing 0x{}",
          left && right ? "both motors" : left ? "left motor" : "right motor",
          Integer.toHexString(doing));
      desired.setVel(0);
      desired.setDeltaHeading(0);
    }
    lastFiredNanos = now;
    doit(robot);
    return desired;
  }

  private void doit(ArRobot robot) {
    if (count == -1 || !going) {
      count = cyclesToMove;
      going = true;
      sideStalled = (robot.isLeftMotorStalled() ? 1 : 0) + (robot.isRightMotorStalled() ? 2 : 0);
      if ((doing & TURN) != 0) {
        double rightDist = RobotSensing.polarDistance(robot, -120, -60);
        double leftDist = RobotSensing.polarDistance(robot, 60, 120);
        int turnDirection;
        if (sideStalled == 1) {
          turnDirection = -1;
        } else if (sideStalled == 2) {
          turnDirection = 1;
        } else if (rightDist < leftDist) {
          turnDirection = 1;
        } else {
          turnDirection = -1;
        }
        desiredHeading = robot.getTh() + turnDirection * degreesToTurn;
      } else if ((doing & TURN_LEFT) != 0) {
        desiredHeading = robot.getTh() + degreesToTurn;
      } else if ((doing & TURN_RIGHT) != 0) {
        desiredHeading = robot.getTh() - degreesToTurn;
      }
    } else {
      count--;
    }

    boolean transFired = false;
    if ((doing & MOVEMASK) != 0) {
      if ((doing & TURNMASK) == 0) {
        desired.setRotVel(0);
      }
      double dist =
          (doing & FORWARD) != 0
              ? RobotSensing.polarDistance(robot, -120, 120)
              : RobotSensing.polarDistance(robot, 120, -120);
      dist -= robot.getRobotRadius();
      if (count <= 0 || (dist > 0 && dist < obstacleDistance && count <= cyclesToMove / 2)) {
        desired.setVel(0);
      } else {
        desired.setVel((doing & BACK) != 0 ? -speed : speed);
        transFired = true;
      }
    }

    boolean rotFired = false;
    if ((doing & TURNMASK) != 0) {
      if ((doing & MOVEMASK) == 0) {
        desired.setVel(0);
      }
      if (count <= 0
          || degreesToTurn == 0
          || Math.abs(ArMath.subAngle(robot.getTh(), desiredHeading)) < 3) {
        desired.setRotVel(0);
      } else {
        desired.setHeading(desiredHeading);
        rotFired = true;
      }
    }

    if (count <= 0 || (!transFired && !rotFired)) {
      going = false;
      log.info("StallRecover: done");
      desired.reset();
    }
  }
}
