package org.jaria.robot;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;

/**
 * What the robot's cycle is made of, apart from the stages it drives: the robot's lock, the packet
 * handlers, the two task lists, the run-exit callbacks, the loop that repeats the cycle, and the
 * cycle's timing settings and counters. {@link ArRobot#loopOnce()} runs one cycle over these parts;
 * {@link RobotCycle} is their public face.
 *
 * <p>The settings and counters are volatile or atomic: they are set from any thread and read by the
 * cycle thread.
 */
final class CycleParts {

  /** Held by the cycle while it runs tasks, and by user code that must not be interleaved. */
  final ReentrantLock robotLock = new ReentrantLock();

  final PacketRouter router = new PacketRouter();
  final TaskList sensorInterpTasks = new TaskList("sensor interpretation");
  final TaskList userTasks = new TaskList("user");
  final Callbacks runExitCBs = new Callbacks("run exit");
  final RunLoop runLoop;

  private final AtomicLong counter = new AtomicLong();
  private final AtomicLong lockWarnings = new AtomicLong();
  private final AtomicLong overrunWarnings = new AtomicLong();
  private volatile long cycleTimeMs = 100;
  private volatile long cycleWarningTimeMs = 250;
  private volatile boolean cycleChained = true;
  private volatile long lastCycleNanos;

  CycleParts(RunLoop runLoop) {
    this.runLoop = runLoop;
  }

  long counter() {
    return counter.get();
  }

  /** Counts one cycle (or one handshake step) done. */
  void countCycle() {
    counter.incrementAndGet();
  }

  long cycleTimeMs() {
    return cycleTimeMs;
  }

  void setCycleTimeMs(long ms) {
    if (ms <= 0) {
      throw new IllegalArgumentException("cycle time must be positive, got " + ms);
    }
    cycleTimeMs = ms;
  }

  long cycleWarningTimeMs() {
    return cycleWarningTimeMs;
  }

  void setCycleWarningTimeMs(long ms) {
    cycleWarningTimeMs = ms;
  }

  boolean cycleChained() {
    return cycleChained;
  }

  void setCycleChained(boolean chained) {
    cycleChained = chained;
  }

  long lastCycleNanos() {
    return lastCycleNanos;
  }

  void setLastCycleNanos(long nanos) {
    lastCycleNanos = nanos;
  }

  /**
   * Whether a cycle that took {@code tookNanos} on the robot's clock is over the warning time;
   * counts it if so.
   *
   * @return the overrun's number (1 for the first), or 0 if the cycle was not over
   */
  long countIfOverrun(long tookNanos) {
    long warn = cycleWarningTimeMs;
    if (warn > 0 && tookNanos > TimeUnit.MILLISECONDS.toNanos(warn)) {
      return overrunWarnings.incrementAndGet();
    }
    return 0;
  }

  long overruns() {
    return overrunWarnings.get();
  }

  /** Counts a cycle skipped because user code held the lock; returns its number. */
  long countSkipped() {
    return lockWarnings.incrementAndGet();
  }

  long skipped() {
    return lockWarnings.get();
  }
}
