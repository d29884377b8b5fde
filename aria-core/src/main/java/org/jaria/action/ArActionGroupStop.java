package org.jaria.action;

import org.jaria.robot.ArRobot;

/**
 * A group that holds the robot still (ARIA's {@code ArActionGroupStop}): one {@link ArActionStop}
 * at priority 100. Use it with {@link #activateExclusive()}.
 */
public class ArActionGroupStop extends ArActionGroup {

  private final ArActionStop actionStop = new ArActionStop();

  /** Adds the stop action to {@code robot}. */
  public ArActionGroupStop(ArRobot robot) {
    super(robot);
    addAction(actionStop, 100);
  }

  /** The stop action. */
  public ArActionStop getActionStop() {
    return actionStop;
  }
}
