package org.jaria.action;

import org.jaria.range.ArRangeBuffer;
import org.jaria.robot.ArRobot;

/**
 * Slows down and turns away from obstacles in front of the robot (ARIA's {@code
 * ArActionAvoidFront}). It looks at every range device of the robot in the sector from −70° to 70°.
 * When the closest reading is nearer than the obstacle distance (measured from the robot's edge),
 * it turns by the turn amount each cycle, away from the side the obstacle is on, and keeps turning
 * the same way until the way is clear; it drives at the avoid velocity scaled by how close the
 * obstacle is, and stops when the obstacle is nearer than half the obstacle distance. If it has
 * turned all the way round without clearing, it halves its turn amount.
 *
 * <p>If the robot's parameters say it has table-sensing IRs (PeopleBot) and {@code
 * useTableIRIfAvail} is true, a triggered IR also counts as an obstacle: it turns away from that
 * side and stops.
 *
 * <p>The thesis's obstacle-avoidance example uses two of them: {@code new ArActionAvoidFront("Avoid
 * Front Near", 225, 0)} at priority 50 and a default one at 49.
 */
public class ArActionAvoidFront extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private final Sectors quadrants = new Sectors();
  private volatile double obsDist;
  private volatile double avoidVel;
  private volatile double turnAmountParam;
  private volatile boolean useTableIRIfAvail;
  private int turning;
  private double turnAmount;

  /** "avoid front obstacles" with ARIA's defaults: 450 mm, 200 mm/s, 15°, table IRs used. */
  public ArActionAvoidFront() {
    this("avoid front obstacles");
  }

  /** An action with ARIA's default parameters and this name. */
  public ArActionAvoidFront(String name) {
    this(name, 450, 200, 15, true);
  }

  /** An action with this obstacle distance and avoid velocity, turning 15° with table IRs used. */
  public ArActionAvoidFront(String name, double obstacleDistance, double avoidVelocity) {
    this(name, obstacleDistance, avoidVelocity, 15, true);
  }

  /** An action with this obstacle distance, avoid velocity and turn amount, table IRs used. */
  public ArActionAvoidFront(
      String name, double obstacleDistance, double avoidVelocity, double turnAmount) {
    this(name, obstacleDistance, avoidVelocity, turnAmount, true);
  }

  /**
   * An avoid-front action.
   *
   * @param name the action's name
   * @param obstacleDistance distance from the robot's edge at which to start turning, mm
   * @param avoidVelocity velocity while avoiding (scaled down as the obstacle nears), mm/s
   * @param turnAmount degrees to turn per cycle while avoiding
   * @param useTableIRIfAvail also avoid what the table-sensing IRs see, if the robot has them
   */
  public ArActionAvoidFront(
      String name,
      double obstacleDistance,
      double avoidVelocity,
      double turnAmount,
      boolean useTableIRIfAvail) {
    super(name, "Slows down and avoids obstacles in front of the robot.");
    this.obsDist = obstacleDistance;
    this.avoidVel = avoidVelocity;
    this.turnAmountParam = turnAmount;
    this.useTableIRIfAvail = useTableIRIfAvail;
  }

  /** Distance from the robot's edge at which avoiding starts, mm. */
  public double getObstacleDistance() {
    return obsDist;
  }

  /** Sets the distance at which avoiding starts, mm. */
  public void setObstacleDistance(double mm) {
    obsDist = mm;
  }

  /** Velocity while avoiding, mm/s. */
  public double getAvoidVelocity() {
    return avoidVel;
  }

  /** Sets the velocity while avoiding, mm/s. */
  public void setAvoidVelocity(double mmPerSec) {
    avoidVel = mmPerSec;
  }

  /** Degrees turned per cycle while avoiding. */
  public double getTurnAmount() {
    return turnAmountParam;
  }

  /** Sets the degrees turned per cycle while avoiding. */
  public void setTurnAmount(double degrees) {
    turnAmountParam = degrees;
  }

  /** Whether table-sensing IRs are used when the robot has them. */
  public boolean getUseTableIRIfAvail() {
    return useTableIRIfAvail;
  }

  /** Sets whether table-sensing IRs are used when the robot has them. */
  public void setUseTableIRIfAvail(boolean use) {
    useTableIRIfAvail = use;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    if (currentDesired.getDeltaHeadingStrength() >= 1.0) {
      // A higher priority has taken the heading: start afresh next time.
      turning = 0;
    }
    desired.reset();
    ArRangeBuffer.Closest closest = RobotSensing.closestPolar(robot, -70, 70);
    double dist =
        (closest == null ? RobotSensing.NOTHING : closest.distance()) - robot.getRobotRadius();
    boolean tableIr = useTableIRIfAvail && RobotSensing.hasTableSensingIR(robot);
    boolean leftIr = tableIr && RobotSensing.isLeftTableSensingIRTriggered(robot);
    boolean rightIr = tableIr && RobotSensing.isRightTableSensingIRTriggered(robot);
    boolean irClear = !leftIr && !rightIr;

    if (dist > obsDist && irClear) {
      if (turning != 0) {
        desired.setDeltaHeading(0);
        turning = 0;
        return desired;
      }
      return null;
    }

    if (turning == 0) {
      if (leftIr) {
        turning = 1;
      } else if (rightIr) {
        turning = -1;
      } else if (closest != null && closest.angle() < 0) {
        turning = 1;
      } else {
        turning = -1;
      }
      turnAmount = turnAmountParam;
      quadrants.clear();
    }

    quadrants.update(robot.getTh());
    if (quadrants.didAll()) {
      quadrants.clear();
      turnAmount /= 2;
      if (turnAmount == 0) {
        turnAmount = turnAmountParam;
      }
    }

    desired.setDeltaHeading(turning * turnAmount);
    if (dist > obsDist / 2 && irClear) {
      desired.setVel(avoidVel * dist / obsDist);
    } else {
      desired.setVel(0);
    }
    return desired;
  }
}
