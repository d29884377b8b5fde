package org.jaria.net.arnl;

import java.util.Objects;
import org.jaria.action.ArActionGroup;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.geom.ArPose;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.Points;
import org.jaria.net.provider.PathPlanningInfo;

/**
 * Serves SonARNL's {@link ArPathPlanningTask} to monitors and to the goto mode: the planned path,
 * the local planner's search area, the state, and goals to go to.
 */
public final class ArnlPathPlanning implements PathPlanningInfo {

  private final ArPathPlanningTask path;

  /** Serves {@code path}. */
  public ArnlPathPlanning(ArPathPlanningTask path) {
    this.path = Objects.requireNonNull(path, "path");
  }

  @Override
  public PathSnapshot getPathState() {
    ArPathPlanningTask.PathPlanningState s = path.getState();
    return new PathSnapshot(
        s.name(),
        path.getStatusString(),
        s == ArPathPlanningTask.PathPlanningState.NOT_INITIALIZED ? null : path.getCurrentGoal(),
        Points.of(path.getCurrentPath()),
        Points.of(path.getLocalSearchArea()));
  }

  @Override
  public String getStatusString() {
    return path.getStatusString();
  }

  @Override
  public boolean pathPlanToPose(ArPose goal, boolean useHeading) {
    return path.pathPlanToPose(goal, useHeading);
  }

  @Override
  public boolean pathPlanToGoal(String goalName) {
    return path.pathPlanToGoal(goalName);
  }

  @Override
  public void cancelPathPlan() {
    path.cancelPathPlan();
  }

  @Override
  public ArActionGroup getActionGroup() {
    return path.getPathPlanActionGroup();
  }

  /** The task served. */
  public ArPathPlanningTask getTask() {
    return path;
  }
}
