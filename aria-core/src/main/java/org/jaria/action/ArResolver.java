package org.jaria.action;

import java.util.List;
import org.jaria.robot.ArRobot;

/**
 * Combines what the actions want into one desire per cycle (ARIA's {@code ArResolver}). The robot
 * uses an {@link ArPriorityResolver} unless told otherwise ({@code ArRobot.setResolver}).
 */
public interface ArResolver {

  /** An action and its priority (higher is more important). */
  record PrioritizedAction(int priority, ArAction action) {}

  /**
   * Fires the active actions and combines their desires.
   *
   * @param actions every action of the robot, highest priority first; for equal priorities in the
   *     order they were added
   * @return the combined desire (never null)
   */
  ArActionDesired resolve(List<PrioritizedAction> actions, ArRobot robot);

  /** A name for logs. */
  default String getName() {
    return getClass().getSimpleName();
  }
}
