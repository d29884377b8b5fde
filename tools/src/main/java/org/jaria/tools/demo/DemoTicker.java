package org.jaria.tools.demo;

import java.util.concurrent.TimeUnit;
import java.util.function.IntConsumer;
import org.jaria.robot.ArRobot;

/**
 * The demos' clock on the wall: once a second it hands the second's number to a callback (to print
 * a status line or press a scripted key), and after the demo's time limit it stops the robot. The
 * thread is named, and {@link #close()} stops and joins it, so a demo leaves nothing running.
 */
final class DemoTicker implements AutoCloseable {

  private final String name;
  private final int seconds;
  private Thread thread;

  /**
   * @param name the thread's name
   * @param seconds how long the demo runs; 0 until the robot stops by itself
   */
  DemoTicker(String name, int seconds) {
    this.name = name;
    this.seconds = seconds;
  }

  /** Starts ticking for {@code robot} (call once, when the robot runs). */
  synchronized void start(ArRobot robot, IntConsumer everySecond) {
    if (thread != null) {
      throw new IllegalStateException("this ticker is already running");
    }
    thread = new Thread(() -> tick(robot, everySecond), name);
    thread.setDaemon(true);
    thread.start();
  }

  private void tick(ArRobot robot, IntConsumer everySecond) {
    long start = System.nanoTime();
    try {
      for (int s = 1; seconds == 0 || s <= seconds; s++) {
        // Pacing a demo for a person to watch, not synchronisation: it only decides when to print.
        TimeUnit.NANOSECONDS.sleep(start + TimeUnit.SECONDS.toNanos(s) - System.nanoTime());
        if (!robot.isRunning()) {
          return;
        }
        everySecond.accept(s);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      return;
    }
    robot.stopRunning();
  }

  /** Stops the ticker (if it still runs) and waits for its thread to end. */
  @Override
  public void close() {
    Thread t;
    synchronized (this) {
      t = thread;
    }
    if (t != null) {
      t.interrupt();
      try {
        t.join(TimeUnit.SECONDS.toMillis(5));
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }
}
