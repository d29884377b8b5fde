package org.jaria.web.source;

import java.util.concurrent.TimeUnit;
import org.jaria.action.ArActionInput;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.jaria.web.control.ControlCommand;
import org.jaria.web.control.Controls;

/**
 * Drives an {@link ArRobot} for viewers: an {@link ArActionInput} above every other action carries
 * the arrow keys' velocities (and path planning's actions are switched off); a goal switches the
 * robot's other actions off and path planning's on, as a server's goto mode does. A drive command
 * holds for {@link ControlCommand#DRIVE_HOLD_MILLIS} ms of the robot's clock and then the robot
 * stops by itself (a task in its cycle checks), so a viewer that disconnects or stops sending
 * cannot leave it driving. Close it to take the action and the task away again.
 */
public final class RobotDriver implements Controls.Driver, AutoCloseable {

  /**
   * The action's priority: above path planning's (50) and its lost/slow-down actions (140, 150).
   */
  public static final int PRIORITY = 200;

  private static final String TASK = "web view drive hold";

  private final ArRobot robot;
  private final ArPathPlanningTask path;
  private final ArActionInput input = new ArActionInput("web view drive");
  private volatile long lastDriveNanos;
  private volatile boolean driving;

  /**
   * Adds the action and the hold check to {@code robot}.
   *
   * @param path its path planning (goals), or null: then goals are refused
   */
  public RobotDriver(ArRobot robot, ArPathPlanningTask path) {
    this.robot = robot;
    this.path = path;
    input.clear();
    robot.addAction(input, PRIORITY);
    robot.addUserTask(TASK, 60, this::hold);
  }

  @Override
  public String robotName() {
    return robot.getName();
  }

  @Override
  public void drive(double vel, double rotVel) {
    if (path != null) {
      if (path.isActive()) {
        path.cancelPathPlan();
      }
      path.getPathPlanActionGroup().deactivate();
    }
    lastDriveNanos = robot.getClock().nanoTime();
    driving = true;
    if (!robot.areMotorsEnabled()) {
      robot.enableMotors();
    }
    input.activate();
    input.setVel(vel);
    input.setRotVel(rotVel);
  }

  /** In the robot's cycle: ends a drive that has not been renewed in time. */
  private void hold() {
    if (driving
        && robot.getClock().nanoTime() - lastDriveNanos
            > TimeUnit.MILLISECONDS.toNanos(ControlCommand.DRIVE_HOLD_MILLIS)) {
      driving = false;
      input.setVel(0);
      input.setRotVel(0);
    }
  }

  @Override
  public boolean goTo(ArPose pose, boolean useHeading) {
    if (path == null) {
      return false;
    }
    driving = false;
    // As a server's goto mode does: the path's actions alone drive (whatever another mode had
    // running stops), with this driver's action standing by, asking for nothing.
    robot.deactivateActions();
    path.getPathPlanActionGroup().activate();
    input.clear();
    input.activate();
    if (!robot.areMotorsEnabled()) {
      robot.enableMotors();
    }
    return path.pathPlanToPose(pose, useHeading);
  }

  @Override
  public void stop() {
    driving = false;
    if (path != null) {
      path.cancelPathPlan();
    }
    input.setVel(0);
    input.setRotVel(0);
  }

  /** Whether a viewer's drive command holds now. */
  public boolean isDriving() {
    return driving;
  }

  @Override
  public void close() {
    robot.remUserTask(TASK);
    robot.remAction(input);
  }
}
