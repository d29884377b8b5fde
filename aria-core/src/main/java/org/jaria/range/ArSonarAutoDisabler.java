package org.jaria.range;

import java.util.concurrent.TimeUnit;
import org.jaria.robot.ArRobot;

/**
 * Switches the sonar off while the robot stands still and on again as soon as it wants to move
 * (ARIA's {@code ArSonarAutoDisabler}): quieter, and other robots' sonar are not confused by a
 * parked one. Sonar go off after the robot has been stopped for more than a second; {@link
 * #supress()} keeps them off whatever happens (e.g. while docking).
 *
 * <p>The decision is the plain function {@link #decide}; the robot runs it as a user task each
 * cycle.
 */
public final class ArSonarAutoDisabler implements AutoCloseable {

  /** The user task's name. */
  public static final String TASK_NAME = "SonarAutoDisabler";

  /** How long the robot must stand still before its sonar go off, ms. */
  public static final long STOPPED_FOR_MS = 1000;

  /** ARIA's "stopped" thresholds: translation mm/s and rotation deg/s. */
  public static final double STOPPED_VEL = 4;

  /** Rotation threshold, deg/s. */
  public static final double STOPPED_ROT_VEL = 1;

  /** What to do with the sonar this cycle. */
  public enum Action {
    /** Nothing. */
    NONE,
    /** Switch them on. */
    ENABLE,
    /** Switch them off. */
    DISABLE
  }

  /**
   * The robot as the disabler sees it in one cycle.
   *
   * @param sonarsOn whether the SIP says the sonar are on
   * @param tryingToMove whether motion is commanded (actions or direct motion)
   * @param vel translational velocity, mm/s
   * @param rotVel rotational velocity, deg/s
   * @param motorsEnabled whether the motors are on
   * @param msSinceMoved time since the robot last moved or wanted to, ms
   */
  public record View(
      boolean sonarsOn,
      boolean tryingToMove,
      double vel,
      double rotVel,
      boolean motorsEnabled,
      long msSinceMoved) {

    /** Whether the robot moves or wants to. */
    public boolean moving() {
      return tryingToMove || Math.abs(vel) >= STOPPED_VEL || Math.abs(rotVel) >= STOPPED_ROT_VEL;
    }
  }

  /** The decision for one cycle (ARIA's rules). */
  public static Action decide(View v, boolean supressed) {
    if (supressed) {
      return v.sonarsOn() ? Action.DISABLE : Action.NONE;
    }
    if (v.moving()) {
      return !v.sonarsOn() && v.motorsEnabled() ? Action.ENABLE : Action.NONE;
    }
    return v.sonarsOn() && v.msSinceMoved() > STOPPED_FOR_MS ? Action.DISABLE : Action.NONE;
  }

  private final ArRobot robot;
  private volatile boolean supressed;
  private long lastMoved;

  /** Adds the disabler's user task to {@code robot}. */
  public ArSonarAutoDisabler(ArRobot robot) {
    this.robot = robot;
    this.lastMoved = robot.getClock().nanoTime();
    robot.addUserTask(TASK_NAME, -50, this::userTask);
  }

  private void userTask() {
    long now = robot.getClock().nanoTime();
    View v =
        new View(
            robot.areSonarsEnabled(),
            robot.isTryingToMove(),
            robot.getVel(),
            robot.getRotVel(),
            robot.areMotorsEnabled(),
            TimeUnit.NANOSECONDS.toMillis(now - lastMoved));
    if (supressed || v.moving()) {
      lastMoved = now;
    }
    switch (decide(v, supressed)) {
      case ENABLE -> robot.enableSonar();
      case DISABLE -> robot.disableSonar();
      case NONE -> {}
    }
  }

  /** Keeps the sonar off until {@link #unsupress()}. */
  public void supress() {
    supressed = true;
  }

  /** Lets the sonar follow the robot's motion again. */
  public void unsupress() {
    supressed = false;
  }

  /** Whether the sonar are held off. */
  public boolean isSupressed() {
    return supressed;
  }

  /** Removes the user task. */
  @Override
  public void close() {
    robot.remUserTask(TASK_NAME);
  }
}
