package org.jaria.net.provider;

import org.jaria.geom.ArPose;
import org.jaria.net.data.PathSnapshot;

/**
 * What the network server needs from a path planner (ARNL's {@code ArPathPlanningTask} via an
 * adapter): the path and search area to draw, and goals to go to. The planner owns its actions:
 * planning to a goal switches them on, {@link #cancelPathPlan()} switches them off.
 *
 * <p>Methods are called from the server's worker threads (never the robot's cycle) and must be
 * thread-safe; {@link #getPathState()} should be cheap.
 */
public interface PathPlanningInfo {

  /** The planner's state, path and local search area now. */
  PathSnapshot getPathState();

  /**
   * Plans to {@code goal} and drives there.
   *
   * @param useHeading whether to turn to the goal's heading at the end
   * @return whether planning started
   */
  boolean pathPlanToPose(ArPose goal, boolean useHeading);

  /**
   * Plans to the map goal called {@code goalName} and drives there.
   *
   * @return whether there is such a goal and planning started
   */
  boolean pathPlanToGoal(String goalName);

  /** Stops going to the goal (the robot stops). */
  void cancelPathPlan();
}
