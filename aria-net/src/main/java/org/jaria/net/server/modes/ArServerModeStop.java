package org.jaria.net.server.modes;

import org.jaria.action.ArActionGroupStop;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.CallPolicy;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Stops the robot and keeps it stopped (ArNetworking's {@code ArServerModeStop}): an {@link
 * ArActionGroupStop} activated exclusively. Usually the default mode. Client request: {@code
 * "stop"}, a {@link CallPolicy#SAFETY} request: however many commands wait for the robot's cycle,
 * it is applied at the next cycle.
 */
public class ArServerModeStop extends ArServerMode {

  private final ArActionGroupStop group;

  /** Registers {@code "stop"} with {@code server}. */
  public ArServerModeStop(ArServerBase server, ArRobot robot) {
    super(server, robot, "Stop");
    group = new ArActionGroupStop(robot);
    withRobotLocked(robot, group::deactivate);
    server.addData(
        "stop",
        "stops the robot and keeps it stopped",
        "none",
        "none",
        "Movement",
        Where.CYCLE,
        (client, request, reply) -> activate());
    // A stop jumps the queue of commands and is never refused (see CallPolicy).
    server.setCallPolicy("stop", CallPolicy.SAFETY);
  }

  @Override
  protected void onActivate() {
    robot.clearDirectMotion();
    group.activateExclusive();
    setStatus("Stopping");
  }

  @Override
  protected void onDeactivate() {
    group.deactivate();
  }

  @Override
  protected void userTask() {
    setStatus(robot.isMoving() || Math.abs(robot.getVel()) > 1 ? "Stopping" : "Stopped");
  }
}
