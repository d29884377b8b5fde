package org.jaria.robot;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An ordered list of {@link ArSyncTask}s: one branch of the robot's cycle. Tasks can be added and
 * removed from any thread, also from inside a running task; a change takes effect in the next
 * cycle.
 */
final class TaskList {

  private static final Logger log = LoggerFactory.getLogger(TaskList.class);

  private final String branch;
  private final CopyOnWriteArrayList<ArSyncTask> tasks = new CopyOnWriteArrayList<>();

  TaskList(String branch) {
    this.branch = branch;
  }

  /**
   * Adds a task; a task with the same name is replaced. Equal positions run in the order they were
   * added.
   */
  synchronized ArSyncTask add(String name, int position, Runnable task) {
    remove(name);
    ArSyncTask t = new ArSyncTask(name, position, task);
    List<ArSyncTask> copy = new ArrayList<>(tasks);
    copy.add(t);
    copy.sort(Comparator.comparingInt(ArSyncTask::getPosition).reversed());
    tasks.clear();
    tasks.addAll(copy);
    return t;
  }

  /** Removes the task called {@code name}; returns whether there was one. */
  synchronized boolean remove(String name) {
    return tasks.removeIf(t -> t.getName().equals(name));
  }

  /** The task called {@code name}, or null. */
  ArSyncTask find(String name) {
    for (ArSyncTask t : tasks) {
      if (t.getName().equals(name)) {
        return t;
      }
    }
    return null;
  }

  /** A snapshot of the tasks in running order. */
  List<ArSyncTask> snapshot() {
    return List.copyOf(tasks);
  }

  /** Runs every active task once, isolating failures. */
  void runAll() {
    for (ArSyncTask t : tasks) {
      if (t.getState() != ArSyncTask.State.ACTIVE) {
        continue;
      }
      long start = System.nanoTime();
      try {
        // A user task's bug must not stop the robot's cycle.
        t.runnable().run();
      } catch (RuntimeException e) {
        t.setState(ArSyncTask.State.FAILURE);
        log.error(
            "{} task '{}' threw and is now disabled (set it ACTIVE again to retry)",
            branch,
            t.getName(),
            e);
      }
      t.recordRun(System.nanoTime() - start);
    }
  }
}
