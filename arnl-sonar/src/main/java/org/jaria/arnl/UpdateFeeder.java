package org.jaria.arnl;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.arnl.ArBaseLocalizationTask.UpdateMode;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The cycle side of a localization task ({@link ArBaseLocalizationTask}): a cheap
 * sensor-interpretation step that lets the {@link ScanFeed} note new readings and, once the robot
 * has moved far enough, hands the odometry pose and the fresh readings, prepared, to the filter —
 * inline (synchronous mode) or through a bounded queue to the localization thread (threaded mode),
 * so the robot's cycle never waits for the filter.
 */
final class UpdateFeeder {

  private static final Logger log = LoggerFactory.getLogger(ArBaseLocalizationTask.class);

  /**
   * What one update needs: the odometry pose at the trigger and the readings since the last,
   * prepared in the robot's frame at that pose.
   */
  record Input(ArPose encoderPose, SonarScan scan, long generation) {}

  /** Does the update. */
  @FunctionalInterface
  interface Sink {
    void process(Input in);
  }

  private static final Input STOP = new Input(ArPose.ORIGIN, null, -1);

  private final ArRobot robot;
  private final LocalizationParams params;
  private final UpdateMode mode;
  private final ScanFeed feed;
  private final Sink sink;
  private final BlockingQueue<Input> queue = new LinkedBlockingQueue<>(16);
  private final Thread thread;
  private final AtomicLong submitted = new AtomicLong();
  private final AtomicLong processed = new AtomicLong();
  private final AtomicLong dropped = new AtomicLong();
  private final Object idleMonitor = new Object();

  // Set by re-initializations on other threads; a stale value only delays one trigger.
  private volatile ArPose lastTriggerPose;

  UpdateFeeder(
      ArRobot robot,
      LocalizationParams params,
      UpdateMode mode,
      String name,
      ScanFeed feed,
      Sink sink) {
    this.robot = robot;
    this.params = params;
    this.mode = mode;
    this.feed = feed;
    this.sink = sink;
    if (mode == UpdateMode.THREADED) {
      thread = new Thread(this::runThread, name);
      thread.setDaemon(true);
      thread.start();
    } else {
      thread = null;
    }
  }

  /**
   * Runs on the robot's cycle: notes new readings; on enough motion, hands them on.
   *
   * @param active whether updates are wanted (initialized and not idle)
   * @param generation the filter's current generation (updates of older ones are dropped)
   */
  void sensorInterp(boolean active, long generation) {
    feed.note();
    if (!active) {
      return;
    }
    ArPose enc = robot.getEncoderPose();
    ArPose last = lastTriggerPose;
    if (last != null
        && last.findDistanceTo(enc) < params.triggerDistance.getDouble()
        && Math.abs(ArMath.subAngle(enc.th(), last.th())) < params.triggerAngle.getDouble()) {
      return;
    }
    lastTriggerPose = enc;
    Input in = new Input(enc, feed.takeFresh(enc), generation);
    if (mode == UpdateMode.SYNCHRONOUS) {
      sink.process(in);
      return;
    }
    submitted.incrementAndGet();
    if (!queue.offer(in)) {
      if (queue.poll() != null) {
        dropped.incrementAndGet();
        markProcessed();
      }
      queue.offer(in);
      log.warn("localization is falling behind the robot; an update was skipped");
    }
  }

  private void runThread() {
    try {
      while (true) {
        Input in = queue.take();
        if (in.generation() < 0) {
          return;
        }
        try {
          sink.process(in);
        } catch (RuntimeException e) {
          log.error("localization update failed", e);
        } finally {
          markProcessed();
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  private void markProcessed() {
    synchronized (idleMonitor) {
      processed.incrementAndGet();
      idleMonitor.notifyAll();
    }
  }

  /** Forgets queued updates and measures the next trigger from {@code enc}. */
  void restartFrom(ArPose enc) {
    while (queue.poll() != null) {
      markProcessed();
    }
    lastTriggerPose = enc;
  }

  /** Waits until every queued update is done; false on timeout (real milliseconds). */
  boolean awaitIdle(long timeoutMs) throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
    synchronized (idleMonitor) {
      while (processed.get() < submitted.get()) {
        long left = deadline - System.nanoTime();
        if (left <= 0) {
          return false;
        }
        TimeUnit.NANOSECONDS.timedWait(idleMonitor, left);
      }
    }
    return true;
  }

  /** Updates skipped because the thread fell behind. */
  long droppedCount() {
    return dropped.get();
  }

  /** Stops and joins the thread (if any). */
  void stop() {
    if (thread != null && thread.isAlive()) {
      while (queue.poll() != null) {
        markProcessed();
      }
      queue.offer(STOP);
      try {
        thread.join(TimeUnit.SECONDS.toMillis(5));
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      if (thread.isAlive()) {
        thread.interrupt();
      }
    }
  }
}
