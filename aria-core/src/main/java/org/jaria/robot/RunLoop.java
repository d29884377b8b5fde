package org.jaria.robot;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.clock.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a robot's cycle over and over: on the caller's thread ({@link #run}) or on a thread of its
 * own ({@link #runAsync}), chained to SIP arrival (waiting at most two cycle times for one) or
 * paced by the cycle time alone. Stoppable from any thread; the thread is named after the robot and
 * joined by {@link #waitForRunExit}.
 *
 * <p>It knows only the {@link Cycle} it runs and what to do when it ends, not the robot.
 */
final class RunLoop {

  private static final Logger log = LoggerFactory.getLogger(RunLoop.class);

  /** What the loop runs: one cycle at a time, and the wait for what the next one reads. */
  interface Cycle {
    /** The cycle time, ms. */
    long cycleTimeMs();

    /**
     * Waits for the input of the next cycle: the robot's replies while connecting (until {@code
     * start + cycleNanos} at most), or a SIP when cycles are chained to SIPs (until {@code start +
     * 2 * cycleNanos} at most).
     *
     * @return false, at once, if there is no such input (not connected, or cycles paced by the
     *     clock alone): the loop then sleeps until {@code start + cycleNanos}
     */
    boolean awaitInput(long start, long cycleNanos);

    /** Runs one cycle. */
    void runOnce();

    /** Whether the robot is connected or being connected. */
    boolean linked();
  }

  private final String name;
  private final Clock clock;
  private final Cycle cycle;
  private final Runnable onExit;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition wake = lock.newCondition();
  private volatile boolean running;
  private volatile boolean stopRequested;
  private volatile Thread thread;

  /**
   * A loop that runs {@code cycle} on {@code clock}, in a thread named after {@code name}, and
   * calls {@code onExit} each time it ends.
   */
  RunLoop(String name, Clock clock, Cycle cycle, Runnable onExit) {
    this.name = name;
    this.clock = clock;
    this.cycle = cycle;
    this.onExit = onExit;
  }

  boolean isRunning() {
    return running;
  }

  private void claim() {
    lock.lock();
    try {
      if (running) {
        throw new IllegalStateException(
            name + " is already running its cycle; call stopRunning() first");
      }
      running = true;
      stopRequested = false;
    } finally {
      lock.unlock();
    }
  }

  void runAsync(boolean stopRunIfNotConnected) {
    claim();
    Thread t = new Thread(() -> loop(stopRunIfNotConnected), "ArRobot-" + name);
    t.setDaemon(true);
    thread = t;
    t.start();
  }

  void run(boolean stopRunIfNotConnected) {
    claim();
    loop(stopRunIfNotConnected);
  }

  private void loop(boolean stopRunIfNotConnected) {
    try {
      while (!stopRequested) {
        long start = clock.nanoTime();
        long cycleNanos = TimeUnit.MILLISECONDS.toNanos(cycle.cycleTimeMs());
        if (!cycle.awaitInput(start, cycleNanos)) {
          sleepUntil(start + cycleNanos);
        }
        if (stopRequested) {
          break;
        }
        cycle.runOnce();
        if (stopRunIfNotConnected && !cycle.linked()) {
          log.info("{}: not connected, so the cycle stops", name);
          break;
        }
      }
    } finally {
      running = false;
      onExit.run();
    }
  }

  private void sleepUntil(long deadline) {
    lock.lock();
    try {
      while (!stopRequested && clock.nanoTime() < deadline) {
        if (!clock.awaitUntil(lock, wake, deadline)) {
          return;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      stopRequested = true;
    } finally {
      lock.unlock();
    }
  }

  void stopRunning() {
    lock.lock();
    try {
      stopRequested = true;
      wake.signalAll();
    } finally {
      lock.unlock();
    }
  }

  void waitForRunExit() throws InterruptedException {
    Thread t = thread;
    if (t != null && t != Thread.currentThread()) {
      t.join();
    }
  }
}
