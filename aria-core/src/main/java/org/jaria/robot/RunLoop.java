package org.jaria.robot;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.clock.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs the robot's cycle over and over: on the caller's thread ({@link #run}) or on a thread of its
 * own ({@link #runAsync}), chained to SIP arrival (waiting at most two cycle times for one) or
 * paced by the cycle time alone. Stoppable from any thread; the thread is named after the robot and
 * joined by {@link #waitForRunExit}.
 */
final class RunLoop {

  private static final Logger log = LoggerFactory.getLogger(RunLoop.class);

  private final ArRobot robot;
  private final ReentrantLock lock = new ReentrantLock();
  private final Condition wake = lock.newCondition();
  private volatile boolean running;
  private volatile boolean stopRequested;
  private volatile Thread thread;
  private volatile Thread runner;

  RunLoop(ArRobot robot) {
    this.robot = robot;
  }

  boolean isRunning() {
    return running;
  }

  private void claim() {
    lock.lock();
    try {
      if (running) {
        throw new IllegalStateException(
            robot.getName() + " is already running its cycle; call stopRunning() first");
      }
      running = true;
      stopRequested = false;
    } finally {
      lock.unlock();
    }
  }

  void runAsync(boolean stopRunIfNotConnected) {
    claim();
    Thread t = new Thread(() -> loop(stopRunIfNotConnected), "ArRobot-" + robot.getName());
    t.setDaemon(true);
    thread = t;
    t.start();
  }

  void run(boolean stopRunIfNotConnected) {
    claim();
    loop(stopRunIfNotConnected);
  }

  private void loop(boolean stopRunIfNotConnected) {
    runner = Thread.currentThread();
    Clock clock = robot.getClock();
    try {
      while (!stopRequested) {
        long start = clock.nanoTime();
        long cycle = TimeUnit.MILLISECONDS.toNanos(robot.getCycleTime());
        if (robot.isConnecting()) {
          robot.link.waitWhileConnecting(start + cycle);
        } else if (robot.isConnected() && robot.isCycleChained()) {
          robot.link.waitForSip(start + 2 * cycle);
        } else {
          sleepUntil(clock, start + cycle);
        }
        if (stopRequested) {
          break;
        }
        robot.loopOnce();
        if (stopRunIfNotConnected && !robot.isConnected() && !robot.isConnecting()) {
          log.info("{}: not connected, so the cycle stops", robot.getName());
          break;
        }
      }
    } finally {
      running = false;
      runner = null;
      robot.runExitCBs.invokeAll();
    }
  }

  private void sleepUntil(Clock clock, long deadline) {
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

  /** Whether the calling thread is the one running the cycle. */
  boolean isCycleThread() {
    return runner == Thread.currentThread();
  }
}
