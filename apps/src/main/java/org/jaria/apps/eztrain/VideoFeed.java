package org.jaria.apps.eztrain;

import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.RgbImage;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Live video for EZ-Train: a thread ({@code eztrain-video}) that reads frames from an {@link
 * ImageSource} (a camera, the simulator's camera, a folder of images) into the session. In
 * continuous mode it reads frame after frame; in single-frame mode it holds the last frame until
 * {@link #grabFrame()} asks for a new one (ACTS's Continuous / Single Frame / Grab Frame).
 */
final class VideoFeed implements AutoCloseable {

  private static final Logger LOG = LoggerFactory.getLogger(VideoFeed.class);

  /** Frames are read at most this often (a camera's rate; a still source would spin). */
  static final long MIN_FRAME_NANOS = 1_000_000_000L / 30;

  private final ImageSource source;
  private final EzTrainSession session;
  private final Runnable onFrame;
  private final Consumer<Exception> onError;
  private final Thread thread;
  private final Object lock = new Object();
  private boolean continuous = true;
  private boolean grab;
  private volatile boolean running = true;
  private final AtomicLong frames = new AtomicLong();
  private volatile long startNanos;

  /**
   * Starts reading.
   *
   * @param onFrame called on the video thread after each new frame
   * @param onError called on the video thread if the source fails (the feed then stops)
   */
  VideoFeed(
      ImageSource source, EzTrainSession session, Runnable onFrame, Consumer<Exception> onError) {
    this.source = source;
    this.session = session;
    this.onFrame = onFrame;
    this.onError = onError;
    thread = new Thread(this::loop, "eztrain-video");
    thread.setDaemon(true);
    startNanos = System.nanoTime();
    thread.start();
  }

  /** What is being read, e.g. "camera 0 160x120". */
  String describe() {
    return source.describe();
  }

  /** Continuous (true) or single-frame (false) grabbing. */
  void setContinuous(boolean on) {
    synchronized (lock) {
      continuous = on;
      lock.notifyAll();
    }
  }

  /** In single-frame mode, reads one new frame. */
  void grabFrame() {
    synchronized (lock) {
      grab = true;
      lock.notifyAll();
    }
  }

  /** Frames per second read since the feed started. */
  double framesPerSecond() {
    double s = (System.nanoTime() - startNanos) / 1e9;
    return s <= 0 ? 0 : frames.get() / s;
  }

  private void loop() {
    int[] px = new int[source.width() * source.height()];
    long last = System.nanoTime() - MIN_FRAME_NANOS;
    try {
      while (running) {
        synchronized (lock) {
          while (running && !continuous && !grab) {
            lock.wait();
          }
          long wait = last + MIN_FRAME_NANOS - System.nanoTime();
          while (running && !grab && wait > 0) {
            TimeUnit.NANOSECONDS.timedWait(lock, wait);
            wait = last + MIN_FRAME_NANOS - System.nanoTime();
          }
          grab = false;
        }
        last = System.nanoTime();
        if (!running) {
          return;
        }
        if (!source.nextFrame(px)) {
          LOG.info("video source {} has no more frames", source.describe());
          return;
        }
        session.setFrame(new RgbImage(source.width(), source.height(), px.clone()));
        frames.incrementAndGet();
        onFrame.run();
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (IOException | RuntimeException e) {
      if (running) {
        onError.accept(e);
      }
    }
  }

  @Override
  public void close() {
    running = false;
    synchronized (lock) {
      lock.notifyAll();
    }
    source.close();
    try {
      thread.join(5000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
