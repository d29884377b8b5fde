package org.jaria.robot;

import java.util.List;

/**
 * The robot's cycle as ARIA programs drive it: running it ({@code run}, {@code runAsync}, {@code
 * stopRunning}), adding packet handlers, sensor-interpretation tasks and user tasks, the robot's
 * lock, and the cycle's timing (cycle time, warning time, chaining to SIPs) and counters.
 *
 * <p>One cycle ({@link ArRobot#loopOnce()}) runs packet handlers, sensor-interpretation tasks,
 * actions, state reflection and user tasks, holding the robot's lock while tasks run. {@link
 * ArRobot} is the only implementation: this interface keeps one job of ARIA's large {@code ArRobot}
 * API in a file of its own, and hands every call to the cycle's parts.
 */
public sealed interface RobotCycle permits ArRobot {

  /** Runs when {@link #run} / {@link #runAsync} ends. */
  default void addRunExitCB(Runnable cb) {
    cycle().runExitCBs.add(cb);
  }

  /** Removes a run-exit callback. */
  default void remRunExitCB(Runnable cb) {
    cycle().runExitCBs.remove(cb);
  }

  /**
   * Runs the cycle on the calling thread until {@link #stopRunning()}.
   *
   * @param stopRunIfNotConnected also stop when the robot is (or becomes) disconnected
   */
  default void run(boolean stopRunIfNotConnected) {
    cycle().runLoop.run(stopRunIfNotConnected);
  }

  /** Runs the cycle on a new thread named after the robot; returns at once. */
  default void runAsync(boolean stopRunIfNotConnected) {
    cycle().runLoop.runAsync(stopRunIfNotConnected);
  }

  /** Asks the cycle to stop; it ends within about two cycle times. */
  default void stopRunning() {
    cycle().runLoop.stopRunning();
  }

  /** Whether the cycle is running. */
  default boolean isRunning() {
    return cycle().runLoop.isRunning();
  }

  /** Waits until the cycle has stopped (at once if it is not running). */
  default void waitForRunExit() throws InterruptedException {
    cycle().runLoop.waitForRunExit();
  }

  /** Adds a packet handler at the end of the list (after the robot's own handlers). */
  default void addPacketHandler(ArPacketHandler h) {
    addPacketHandler(h, ArListPos.LAST);
  }

  /** Adds a packet handler at the front (asked before the robot's own) or the end. */
  default void addPacketHandler(ArPacketHandler h, ArListPos pos) {
    cycle().router.add(h, pos);
  }

  /** Removes a packet handler. */
  default void remPacketHandler(ArPacketHandler h) {
    cycle().router.remove(h);
  }

  /**
   * Adds (or replaces, by name) a sensor-interpretation task; higher positions run first. Range
   * devices and localization use these.
   */
  default ArSyncTask addSensorInterpTask(String taskName, int position, Runnable task) {
    return cycle().sensorInterpTasks.add(taskName, position, task);
  }

  /** Removes a sensor-interpretation task by name. */
  default boolean remSensorInterpTask(String taskName) {
    return cycle().sensorInterpTasks.remove(taskName);
  }

  /** Adds (or replaces, by name) a user task; higher positions run first. */
  default ArSyncTask addUserTask(String taskName, int position, Runnable task) {
    return cycle().userTasks.add(taskName, position, task);
  }

  /** Removes a user task by name. */
  default boolean remUserTask(String taskName) {
    return cycle().userTasks.remove(taskName);
  }

  /** The sensor-interpretation task with this name, or null. */
  default ArSyncTask findSensorInterpTask(String taskName) {
    return cycle().sensorInterpTasks.find(taskName);
  }

  /** The user task with this name, or null. */
  default ArSyncTask findUserTask(String taskName) {
    return cycle().userTasks.find(taskName);
  }

  /** The user tasks in running order. */
  default List<ArSyncTask> getUserTasks() {
    return cycle().userTasks.snapshot();
  }

  /** The sensor-interpretation tasks in running order. */
  default List<ArSyncTask> getSensorInterpTasks() {
    return cycle().sensorInterpTasks.snapshot();
  }

  /**
   * The cycle as a tree, as ARIA's {@code getSyncTaskRoot()} shows it: "SyncTasks" with "Packet
   * Handler" (85), the "Sensor Interp" branch (65) with its tasks, "Action Handler" (55), "State
   * Reflector" (45) and the "User Tasks" branch (25) with its tasks. A snapshot: ask again after
   * adding or removing tasks. {@code System.out.print(robot.getSyncTaskRoot())} prints it.
   */
  default SyncTaskView getSyncTaskRoot() {
    return new SyncTaskView(
        "SyncTasks",
        0,
        true,
        null,
        List.of(
            SyncTaskView.step("Packet Handler", 85),
            SyncTaskView.branch("Sensor Interp", 65, cycle().sensorInterpTasks.snapshot()),
            SyncTaskView.step("Action Handler", 55),
            SyncTaskView.step("State Reflector", 45),
            SyncTaskView.branch("User Tasks", 25, cycle().userTasks.snapshot())));
  }

  /** Locks the robot: the cycle's tasks do not run until {@link #unlock()}. */
  default void lock() {
    cycle().robotLock.lock();
  }

  /** Tries to lock the robot without waiting. */
  default boolean tryLock() {
    return cycle().robotLock.tryLock();
  }

  /** Unlocks the robot. */
  default void unlock() {
    cycle().robotLock.unlock();
  }

  /** Cycles run so far (ARIA's counter, used to tell new sensor readings from old). */
  default long getCounter() {
    return cycle().counter();
  }

  /** Sets the cycle time, ms (default 100, the SIP cycle). */
  default void setCycleTime(long ms) {
    cycle().setCycleTimeMs(ms);
  }

  /** The cycle time, ms. */
  default long getCycleTime() {
    return cycle().cycleTimeMs();
  }

  /**
   * A cycle longer than this, on the robot's clock, logs a warning and is counted ({@link
   * #getCycleOverrunCount()}), ms (default 250; 0 never).
   */
  default void setCycleWarningTime(long ms) {
    cycle().setCycleWarningTimeMs(ms);
  }

  /** The cycle warning time, ms. */
  default long getCycleWarningTime() {
    return cycle().cycleWarningTimeMs();
  }

  /** Whether each cycle waits for a SIP (true, default) or just runs every cycle time. */
  default void setCycleChained(boolean chained) {
    cycle().setCycleChained(chained);
  }

  /** Whether cycles are chained to SIP arrival. */
  default boolean isCycleChained() {
    return cycle().cycleChained();
  }

  /** Real time the last cycle's tasks took, ns. */
  default long getLastCycleNanos() {
    return cycle().lastCycleNanos();
  }

  /**
   * How many cycles took longer than the {@link #setCycleWarningTime cycle warning time} on the
   * robot's clock (each logged a warning, or every hundredth after the first).
   */
  default long getCycleOverrunCount() {
    return cycle().overruns();
  }

  /** How many cycles were skipped because user code held the robot's lock too long. */
  default long getSkippedCycleCount() {
    return cycle().skipped();
  }

  /**
   * The parts the cycle is made of. Java has no package-private interface members, so they are
   * reached through the only implementation.
   */
  private CycleParts cycle() {
    return ((ArRobot) this).cycle;
  }
}
