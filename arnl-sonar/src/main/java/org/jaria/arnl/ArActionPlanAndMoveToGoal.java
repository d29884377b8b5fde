package org.jaria.arnl;

import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;

/**
 * The action that drives the robot along {@link ArPathPlanningTask}'s path (ARNL's {@code
 * ArActionPlanAndMoveToGoal}). It is created and added to the robot by the task; it wants nothing
 * while there is no goal, and stops the robot for a second when a goal ends.
 */
public final class ArActionPlanAndMoveToGoal extends ArAction {

  private final ArPathPlanningTask task;
  private final ArActionDesired desired = new ArActionDesired();

  ArActionPlanAndMoveToGoal(ArPathPlanningTask task) {
    super("PathPlanAndMoveToGoal", "follows the planned path, avoiding obstacles");
    this.task = task;
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    return task.fire(desired);
  }

  /** The task this action belongs to. */
  public ArPathPlanningTask getTask() {
    return task;
  }
}
