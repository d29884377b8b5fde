package org.jaria.acts.server;

import java.io.IOException;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.BlobTracker;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.ImageSource;

/**
 * One frame's work: take the next image from a source, optionally rotate it (camera mounted upside
 * down), and find every channel's blobs with the bank's current tables. Holds the frame buffer and
 * the tracker, so it is used by one thread (the server's pipeline thread, or a training window's
 * refresh loop); the bank may be edited from other threads meanwhile.
 */
public final class VisionPipeline {

  private final ImageSource source;
  private final ChannelBank bank;
  private final BlobTracker tracker = new BlobTracker();
  private final int[] pixels;
  private volatile TrackerSettings settings;
  private volatile boolean inverted;

  /** A pipeline reading {@code source} and classifying with {@code bank}. */
  public VisionPipeline(ImageSource source, ChannelBank bank, TrackerSettings settings) {
    this.source = source;
    this.bank = bank;
    this.settings = settings;
    this.pixels = new int[source.width() * source.height()];
  }

  /** The image source. */
  public ImageSource source() {
    return source;
  }

  /** The channels. */
  public ChannelBank bank() {
    return bank;
  }

  /** Frame width. */
  public int width() {
    return source.width();
  }

  /** Frame height. */
  public int height() {
    return source.height();
  }

  /** Changes the tracker settings from the next frame on (any thread). */
  public void setSettings(TrackerSettings settings) {
    this.settings = settings;
  }

  /** The tracker settings. */
  public TrackerSettings getSettings() {
    return settings;
  }

  /** Rotates every frame by 180° before tracking (ACTS's inverted image); any thread. */
  public void setInverted(boolean inverted) {
    this.inverted = inverted;
  }

  /**
   * Reads the next frame and finds its blobs.
   *
   * @return false if the source has no more frames ({@code out} is then unchanged)
   * @throws IOException if the source failed
   */
  public boolean processNext(BlobFrame out) throws IOException {
    if (!source.nextFrame(pixels)) {
      return false;
    }
    if (inverted) {
      for (int i = 0, j = pixels.length - 1; i < j; i++, j--) {
        int t = pixels[i];
        pixels[i] = pixels[j];
        pixels[j] = t;
      }
    }
    tracker.track(pixels, source.width(), source.height(), bank.tables(), settings, out);
    return true;
  }

  /** A copy of the last frame's pixels (after rotation), for displays. */
  public int[] lastFrame() {
    return pixels.clone();
  }
}
