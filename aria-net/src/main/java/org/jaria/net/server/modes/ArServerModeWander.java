package org.jaria.net.server.modes;

import org.jaria.action.ArActionGroupWander;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.Where;
import org.jaria.robot.ArRobot;

/**
 * Lets the robot wander, avoiding obstacles (ArNetworking's {@code ArServerModeWander}): ARIA's
 * {@link ArActionGroupWander} activated exclusively. Client request: {@code "wander"}.
 */
public class ArServerModeWander extends ArServerMode {

  private final ArActionGroupWander group;

  /** Registers {@code "wander"} with {@code server}. */
  public ArServerModeWander(ArServerBase server, ArRobot robot) {
    super(server, robot, "Wander");
    group = new ArActionGroupWander(robot);
    withRobotLocked(robot, group::deactivate);
    server.addData(
        "wander",
        "makes the robot wander around, avoiding obstacles",
        "none",
        "none",
        "Movement",
        Where.CYCLE,
        (client, request, reply) -> activate());
  }

  /** The wander actions (to add, say, an ArActionLost at a high priority). */
  public ArActionGroupWander getActionGroup() {
    return group;
  }

  @Override
  protected void onActivate() {
    robot.clearDirectMotion();
    robot.enableMotors();
    group.activateExclusive();
    setStatus("Wandering");
  }

  @Override
  protected void onDeactivate() {
    group.deactivate();
  }
}
