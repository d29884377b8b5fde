package org.jaria.robot;

import java.util.List;
import java.util.Objects;

/**
 * A read-only picture of the robot's cycle as a tree (what ARIA's {@code getSyncTaskRoot()} shows):
 * the root, then in running order the packet handlers, the sensor-interpretation tasks, the action
 * handler, the state reflector and the user tasks, each with its name and position (higher runs
 * earlier). Get one from {@link ArRobot#getSyncTaskRoot()}; it does not change when tasks are added
 * or removed later, so ask again to see them.
 *
 * <p>The nodes of your own tasks carry the live {@link ArSyncTask} in {@link #task()}, so a program
 * can find a task by name and suspend it. The robot's built-in steps have no task object and always
 * run.
 *
 * @param name the node's name, e.g. "User Tasks" or the name a task was added with
 * @param position where it runs among its siblings: higher first
 * @param branch whether the node groups others (the root, "Sensor Interp", "User Tasks"), even
 *     while it has no children
 * @param task the live task for a sensor-interpretation or user task, else null
 * @param children the nodes below this one, in running order (empty for a leaf)
 */
public record SyncTaskView(
    String name, int position, boolean branch, ArSyncTask task, List<SyncTaskView> children) {

  /** Checks the name and copies the children. */
  public SyncTaskView {
    Objects.requireNonNull(name, "name");
    children = List.copyOf(children);
  }

  /** A leaf for one of the robot's tasks. */
  static SyncTaskView leaf(ArSyncTask t) {
    return new SyncTaskView(t.getName(), t.getPosition(), false, t, List.of());
  }

  /** A leaf for a built-in step of the cycle. */
  static SyncTaskView step(String name, int position) {
    return new SyncTaskView(name, position, false, null, List.of());
  }

  /** A branch holding {@code tasks} in running order. */
  static SyncTaskView branch(String name, int position, List<ArSyncTask> tasks) {
    return new SyncTaskView(
        name, position, true, null, tasks.stream().map(SyncTaskView::leaf).toList());
  }

  /** Whether the node runs: a task's state is {@link ArSyncTask.State#ACTIVE}; built-ins always. */
  public boolean isActive() {
    return task == null || task.getState() == ArSyncTask.State.ACTIVE;
  }

  /** This node or the first node below it called {@code nodeName} (depth first), or null. */
  public SyncTaskView find(String nodeName) {
    if (name.equals(nodeName)) {
      return this;
    }
    for (SyncTaskView c : children) {
      SyncTaskView f = c.find(nodeName);
      if (f != null) {
        return f;
      }
    }
    return null;
  }

  /** The tree, one node per line, indented by depth, as ARIA's {@code log()} prints it. */
  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder();
    append(sb, 0);
    return sb.toString();
  }

  private void append(StringBuilder sb, int depth) {
    sb.append("  ".repeat(depth)).append(name).append(" (").append(position).append(')');
    if (task != null) {
      sb.append(' ').append(task.getState());
    }
    sb.append('\n');
    for (SyncTaskView c : children) {
      c.append(sb, depth + 1);
    }
  }
}
