package org.jaria.net.sim;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.jaria.net.data.VideoFrame;
import org.jaria.net.provider.VideoSource;
import org.jaria.sim.camera.SimCamera;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated camera as the server's video (what a real robot's camera or ACTS would give): a
 * thread of its own renders the camera's view a few times a second and compresses it to JPEG, but
 * only while some client has asked for video in the last two seconds, so an unwatched camera costs
 * nothing. {@link #getLatestFrame()} returns the last frame at once.
 */
public final class SimCameraVideo implements VideoSource, AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(SimCameraVideo.class);

  /** Frames stop being made this long after the last request. */
  private static final long WATCHED_NANOS = TimeUnit.SECONDS.toNanos(2);

  private final SimCamera camera;
  private final String name;
  private final ScheduledExecutorService thread;
  private final int[] pixels;
  private final BufferedImage image;
  private volatile VideoFrame latest;
  private volatile long lastAskedNanos = System.nanoTime() - 2 * WATCHED_NANOS;
  private long sequence;

  /**
   * Video from {@code camera}.
   *
   * @param framesPerSecond how often a frame is made while watched
   */
  public SimCameraVideo(SimCamera camera, String name, double framesPerSecond) {
    this.camera = camera;
    this.name = name;
    this.pixels = new int[camera.getWidth() * camera.getHeight()];
    this.image =
        new BufferedImage(camera.getWidth(), camera.getHeight(), BufferedImage.TYPE_INT_RGB);
    this.thread =
        Executors.newSingleThreadScheduledExecutor(
            r -> {
              Thread t = new Thread(r, "jaria-net-camera-" + name);
              t.setDaemon(true);
              return t;
            });
    long period = Math.max(1, (long) (1e9 / framesPerSecond));
    var unused = thread.scheduleAtFixedRate(this::capture, 0, period, TimeUnit.NANOSECONDS);
  }

  private void capture() {
    if (System.nanoTime() - lastAskedNanos > WATCHED_NANOS && latest != null) {
      return;
    }
    try {
      camera.render(pixels);
      image.setRGB(0, 0, camera.getWidth(), camera.getHeight(), pixels, 0, camera.getWidth());
      ByteArrayOutputStream out = new ByteArrayOutputStream(16 * 1024);
      if (!ImageIO.write(image, "jpg", out)) {
        throw new UncheckedIOException(new IOException("this Java has no JPEG writer"));
      }
      latest =
          new VideoFrame(
              ++sequence,
              VideoFrame.Format.JPEG,
              camera.getWidth(),
              camera.getHeight(),
              out.toByteArray());
    } catch (IOException | RuntimeException e) {
      // A failing frame must not stop the next ones (the executor would cancel the task).
      if (sequence % 100 == 0) {
        log.warn("the simulated camera could not make a frame: {}", e.toString());
      }
    }
  }

  @Override
  public String getName() {
    return name;
  }

  @Override
  public VideoFrame getLatestFrame() {
    lastAskedNanos = System.nanoTime();
    return latest;
  }

  /** Stops making frames and waits for the thread to end. */
  @Override
  public void close() {
    thread.shutdownNow();
    try {
      if (!thread.awaitTermination(5, TimeUnit.SECONDS)) {
        log.warn("the camera thread of {} did not stop within 5 s", name);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
