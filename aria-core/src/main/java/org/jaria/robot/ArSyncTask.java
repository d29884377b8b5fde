package org.jaria.robot;

/**
 * A task that runs once per robot cycle (ARIA's {@code ArSyncTask}): a sensor-interpretation task
 * or a user task. Tasks run in order of decreasing {@link #getPosition() position}.
 *
 * <p>A task that throws is not allowed to take the robot down: the exception is logged, the task
 * moves to {@link State#FAILURE} and is skipped from then on, and every other task keeps running.
 * Call {@link #setState} with {@link State#ACTIVE} to give it another chance.
 */
public final class ArSyncTask {

  /** Whether a task runs. */
  public enum State {
    /** Runs every cycle. */
    ACTIVE,
    /** Skipped until made active again. */
    SUSPEND,
    /** Threw an exception; skipped until made active again. */
    FAILURE
  }

  private final String name;
  private final int position;
  private final Runnable task;
  private volatile State state = State.ACTIVE;
  private volatile long lastRunNanos;

  ArSyncTask(String name, int position, Runnable task) {
    this.name = name;
    this.position = position;
    this.task = task;
  }

  /** The task's name, unique within its list. */
  public String getName() {
    return name;
  }

  /** Its position: higher runs earlier. */
  public int getPosition() {
    return position;
  }

  /** Its state. */
  public State getState() {
    return state;
  }

  /** Suspends, resumes or re-activates the task. */
  public void setState(State s) {
    state = s;
  }

  /** How long the task took the last time it ran, in nanoseconds of real time. */
  public long getLastRunNanos() {
    return lastRunNanos;
  }

  Runnable runnable() {
    return task;
  }

  void recordRun(long nanos) {
    lastRunNanos = nanos;
  }

  @Override
  public String toString() {
    return name + "@" + position + " (" + state + ")";
  }
}
