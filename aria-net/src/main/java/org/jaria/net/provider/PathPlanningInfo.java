package org.jaria.net.provider;

import org.jaria.action.ArActionGroup;
import org.jaria.geom.ArPose;
import org.jaria.net.data.PathSnapshot;

/**
 * What the network server needs from a path planner (ARNL's {@code ArPathPlanningTask} via an
 * adapter such as {@code org.jaria.net.arnl.ArnlPathPlanning} in arnl-net): the path and search
 * area to draw, and goals to go to. The planner drives with its own action group, which the goto
 * mode switches on when it becomes active and off when another mode takes over.
 *
 * <p>Methods are called from the server's worker and publisher threads, and {@link
 * #getStatusString()} and {@link #cancelPathPlan()} also from the robot's cycle: all must be
 * thread-safe, and those two quick.
 */
public interface PathPlanningInfo {

  /** The planner's state, path and local search area now (publisher thread, at client rates). */
  PathSnapshot getPathState();

  /** What the planner is doing, for people (called every robot cycle while goto is active). */
  String getStatusString();

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

  /** The actions that follow the planned path (activated exclusively by the goto mode). */
  ArActionGroup getActionGroup();
}
