package org.jaria.net.arnl;

import java.util.Objects;
import java.util.function.Supplier;
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

  private final Supplier<ArPathPlanningTask> current;

  /** Serves {@code path}. */
  public ArnlPathPlanning(ArPathPlanningTask path) {
    Objects.requireNonNull(path, "path");
    this.current = () -> path;
  }

  /** Serves whichever task {@code current} gives (a new one after a map change). */
  ArnlPathPlanning(Supplier<ArPathPlanningTask> current) {
    this.current = current;
  }

  @Override
  public PathSnapshot getPathState() {
    ArPathPlanningTask path = current.get();
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
    return current.get().getStatusString();
  }

  @Override
  public boolean pathPlanToPose(ArPose goal, boolean useHeading) {
    return current.get().pathPlanToPose(goal, useHeading);
  }

  @Override
  public boolean pathPlanToGoal(String goalName) {
    return current.get().pathPlanToGoal(goalName);
  }

  @Override
  public void cancelPathPlan() {
    current.get().cancelPathPlan();
  }

  @Override
  public ArActionGroup getActionGroup() {
    return current.get().getPathPlanActionGroup();
  }

  /** The task served. */
  public ArPathPlanningTask getTask() {
    return current.get();
  }
}
