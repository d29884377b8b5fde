package org.jaria.net.video;

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
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Video for the network server from anything that can fill a picture: a thread of its own grabs a
 * frame a few times a second and compresses it to JPEG, but only while some client has asked for
 * video in the last two seconds, so an unwatched camera costs nothing. {@link #getLatestFrame()}
 * returns the last frame at once (the server's publisher thread must never wait for a camera).
 */
public class JpegVideo implements VideoSource, AutoCloseable {

  /** Fills a picture: 0xRRGGBB pixels, row by row. */
  @FunctionalInterface
  public interface Grabber {
    /**
     * Fills {@code rgb} (width × height pixels) with the newest picture.
     *
     * @return false if there is no new picture (the previous frame stays)
     * @throws IOException if the camera failed (logged; the next grab is tried as usual)
     */
    boolean grab(int[] rgb) throws IOException;
  }

  private static final Logger log = LoggerFactory.getLogger(JpegVideo.class);

  /** Frames stop being made this long after the last request. */
  private static final long WATCHED_NANOS = TimeUnit.SECONDS.toNanos(2);

  private final String name;
  private final int width;
  private final int height;
  private final Grabber grabber;
  private final ScheduledExecutorService thread;
  private final int[] pixels;
  private final BufferedImage image;
  private volatile VideoFrame latest;
  private volatile long lastAskedNanos = System.nanoTime() - 2 * WATCHED_NANOS;
  private long sequence;
  private long failures;

  /**
   * Video of {@code width} × {@code height} pictures from {@code grabber}.
   *
   * @param framesPerSecond how often a frame is made while watched
   */
  public JpegVideo(String name, int width, int height, double framesPerSecond, Grabber grabber) {
    if (width <= 0 || height <= 0 || !(framesPerSecond > 0)) {
      throw new IllegalArgumentException(
          "video needs a positive size and frame rate, got "
              + width
              + "x"
              + height
              + " at "
              + framesPerSecond
              + " frames/s");
    }
    this.name = name;
    this.width = width;
    this.height = height;
    this.grabber = grabber;
    this.pixels = new int[width * height];
    this.image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
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
      if (!grabber.grab(pixels)) {
        return;
      }
      image.setRGB(0, 0, width, height, pixels, 0, width);
      ByteArrayOutputStream out = new ByteArrayOutputStream(16 * 1024);
      if (!ImageIO.write(image, "jpg", out)) {
        throw new UncheckedIOException(new IOException("this Java has no JPEG writer"));
      }
      latest = new VideoFrame(++sequence, VideoFrame.Format.JPEG, width, height, out.toByteArray());
    } catch (IOException | RuntimeException e) {
      // A failing frame must not stop the next ones (the executor would cancel the task).
      if (failures++ % 100 == 0) {
        log.warn("camera {} could not make a frame: {}", name, e.toString());
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
