package org.jaria.action;

import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArCommands;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Backs away when the robot's front infrared sensors trigger (ARIA's {@code ArActionIRs}), like
 * {@link ArActionBumpers} but before contact. It works on robots whose parameters declare
 * table-sensing IRs and list {@code IRUnit}s (PeopleBots). An IR counts as triggered after it has
 * read "something there" for its {@code cycles} consecutive cycles. When a front IR (one with a
 * positive x on the robot) triggers while driving forward faster than 50 mm/s, the action sends an
 * emergency stop, backs up at the back-off speed for the back-off time, then turns away from the
 * IRs' mean direction (for at most the turn time), then holds still for a second.
 *
 * <p>IR states come from the fourth IOpac digital-input byte on robots with the new table-sensing
 * IRs (request IOpacs), else from the SIP's DIGIN byte, where 0 means triggered.
 */
public class ArActionIRs extends ArAction {

  private static final Logger log = LoggerFactory.getLogger(ArActionIRs.class);
  private static final double TURN_RANGE = 135;
  private static final long STOP_TIME_MS = 1000;

  private final ArActionDesired desired = new ArActionDesired();
  private volatile double backOffSpeed;
  private volatile int backOffTime;
  private volatile int turnTime;
  private volatile boolean setMaximums;
  private int[] cycleCounters = new int[0];
  private boolean firing;
  private double speed;
  private double heading;
  private long startBackNanos;
  private long stoppedSinceNanos = Long.MIN_VALUE / 2;

  /** "IRs" with ARIA's defaults: 100 mm/s, back off 5000 ms, turn 3000 ms, no maximums. */
  public ArActionIRs() {
    this("IRs", 100, 5000, 3000, false);
  }

  /**
   * An IR action.
   *
   * @param name the action's name
   * @param backOffSpeed speed at which to back away, mm/s
   * @param backOffTime how long to back away, ms
   * @param turnTime how long to allow for the turn, ms
   * @param setMaximums kept for ARIA compatibility; ARIA's action never used it either
   */
  public ArActionIRs(
      String name, double backOffSpeed, int backOffTime, int turnTime, boolean setMaximums) {
    super(name, "Reacts to the IRs triggering");
    this.backOffSpeed = backOffSpeed;
    this.backOffTime = backOffTime;
    this.turnTime = turnTime;
    this.setMaximums = setMaximums;
  }

  /** Whether the (unused) set-maximums flag is on. */
  public boolean getSetMaximums() {
    return setMaximums;
  }

  @Override
  public void setRobot(ArRobot r) {
    super.setRobot(r);
    locked(
        () -> {
          cycleCounters = new int[Math.max(0, r.getRobotParams().getNumIR())];
          java.util.Arrays.fill(cycleCounters, 1);
        });
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    ArRobot robot = getRobot();
    long now = robot.getClock().nanoTime();
    desired.reset();
    if (firing) {
      long since = TimeUnit.NANOSECONDS.toMillis(now - startBackNanos);
      if (since < backOffTime) {
        desired.setVel(speed);
        desired.setDeltaHeading(0);
        return desired;
      } else if (since < (long) backOffTime + turnTime
          && Math.abs(ArMath.subAngle(robot.getTh(), heading)) > 3) {
        desired.setVel(0);
        desired.setHeading(heading);
        return desired;
      } else if (TimeUnit.NANOSECONDS.toMillis(now - stoppedSinceNanos) < STOP_TIME_MS) {
        desired.setVel(0);
        desired.setDeltaHeading(0);
        return desired;
      }
      firing = false;
    }

    ArRobotParams p = robot.getRobotParams();
    if (!p.haveTableSensingIR()) {
      return null;
    }
    int numIr = p.getNumIR();
    if (cycleCounters.length != numIr) {
      // The parameters changed when the robot connected.
      cycleCounters = new int[numIr];
      java.util.Arrays.fill(cycleCounters, 1);
    }
    boolean fromIoPacket = p.haveNewTableSensingIR() && robot.getIODigInSize() > 3;
    double angle = 0;
    int counter = 0;
    for (int i = 0; i < numIr && i < 8; i++) {
      int bit = 1 << i;
      boolean triggered;
      if (fromIoPacket) {
        boolean set = (robot.getIODigIn(3) & bit) != 0;
        triggered = p.getIRType(i) != 0 ? !set : set;
      } else {
        triggered = (robot.getDigIn() & bit) == 0;
      }
      if (!triggered) {
        cycleCounters[i] = 1;
      } else if (cycleCounters[i] < p.getIRCycles(i)) {
        cycleCounters[i]++;
      } else {
        cycleCounters[i] = 1;
        if (p.getIRX(i) > 0) {
          angle += Math.toDegrees(Math.atan2(p.getIRY(i), p.getIRX(i)));
          counter++;
        }
      }
    }

    double vel = robot.getVel();
    if (counter > 0 && vel > 50) {
      angle = ArMath.clamp(angle / counter, -TURN_RANGE / 2, TURN_RANGE / 2);
      angle = angle < 0 ? -(TURN_RANGE / 2 + angle) : TURN_RANGE / 2 - angle;
      heading = ArMath.addAngle(robot.getTh(), angle);
      speed = -backOffSpeed;
      startBackNanos = now;
      log.info("ArActionIRs: estopping");
      robot.com(ArCommands.E_STOP);
      firing = true;
      desired.setVel(speed);
      desired.setHeading(heading);
      return desired;
    } else if (counter > 0 && vel > -50 && vel < 50) {
      stoppedSinceNanos = now;
      // ARIA returned an empty desire here: nothing is asked for.
      return desired;
    }
    return null;
  }
}
