package org.jaria.sim;

import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thread that steps a world in real time (times a speed-up). Simulated time still advances in
 * whole ticks; the thread only paces them against the wall clock. If the machine cannot keep up, it
 * runs as fast as it can and says so once.
 */
final class RealTimeRunner {

  private static final Logger log = LoggerFactory.getLogger(RealTimeRunner.class);

  /** What the world thread's name starts with; the world's name follows. */
  static final String THREAD_PREFIX = "jaria-sim-";

  private final SimWorld world;
  private final long realTickNanos;
  private final double speedup;
  private final Thread thread;
  private volatile boolean running = true;
  private volatile int lastIntervalMillis;

  RealTimeRunner(SimWorld world, long tickNanos, double speedup) {
    this.world = world;
    this.realTickNanos = speedup > 0 ? (long) (tickNanos / speedup) : 0;
    this.speedup = speedup;
    this.thread = new Thread(this::run, THREAD_PREFIX + world.getName());
    thread.setDaemon(true);
  }

  void start() {
    thread.start();
  }

  boolean isRunnerThread() {
    return Thread.currentThread() == thread;
  }

  /** Simulated seconds per real second (≤ 0: as fast as it can). */
  double speedup() {
    return speedup;
  }

  int realIntervalMillis() {
    return (int) (realTickNanos / 1_000_000);
  }

  int lastIntervalMillis() {
    return lastIntervalMillis;
  }

  private void run() {
    long start = System.nanoTime();
    long ticks = 0;
    boolean warned = false;
    while (running) {
      long t0 = System.nanoTime();
      try {
        world.step();
      } catch (Throwable e) { // NOPMD: an Error too must not leave ports nobody serves
        if (running && !world.isClosed()) {
          world.worldThreadFailed(e);
        }
        return;
      }
      ticks++;
      long now = System.nanoTime();
      lastIntervalMillis = (int) ((now - t0) / 1_000_000);
      if (realTickNanos == 0) {
        continue;
      }
      long target = start + ticks * realTickNanos;
      long wait = target - now;
      if (wait > 0) {
        LockSupport.parkNanos(wait);
      } else if (-wait > 1_000_000_000L) {
        if (!warned) {
          log.warn(
              "the simulation cannot keep up with the requested speed; running as fast as it can");
          warned = true;
        }
        start = now - ticks * realTickNanos;
      }
    }
  }

  void stopAndJoin() {
    running = false;
    LockSupport.unpark(thread);
    if (Thread.currentThread() == thread) {
      return;
    }
    boolean interrupted = false;
    while (thread.isAlive()) {
      try {
        thread.join();
      } catch (InterruptedException e) {
        interrupted = true;
      }
    }
    if (interrupted) {
      Thread.currentThread().interrupt();
    }
  }
}
