package org.jaria.acts.blob;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.color.ChannelBank;

/**
 * The blobs of one processed frame: for each of the 32 channels, up to 10 blobs, largest first.
 * Channels are numbered 1..32 and blobs 1..count, as in ARIA's {@code ArACTS_1_2}.
 *
 * <p>Stored in primitive arrays so that a tracker can refill the same frame object for every video
 * frame. Not thread-safe: hand a {@link #copy()} to another thread.
 */
public final class BlobFrame {

  private static final int CH = ChannelBank.NUM_CHANNELS;
  private static final int MAX = ChannelBank.MAX_TRACKED_BLOBS;

  int width;
  int height;
  long frameNumber;
  long processNanos;
  final int[] count = new int[CH];
  final int[] area = new int[CH * MAX];
  final int[] xcg = new int[CH * MAX];
  final int[] ycg = new int[CH * MAX];
  final int[] left = new int[CH * MAX];
  final int[] right = new int[CH * MAX];
  final int[] top = new int[CH * MAX];
  final int[] bottom = new int[CH * MAX];
  final double[] cx = new double[CH * MAX];
  final double[] cy = new double[CH * MAX];

  /** An empty frame (no blobs, size 0 × 0). */
  public BlobFrame() {}

  /** Width of the image the blobs were found in. */
  public int width() {
    return width;
  }

  /** Height of the image the blobs were found in. */
  public int height() {
    return height;
  }

  /** A sequence number set by whoever produced the frame (the server counts from 1). */
  public long frameNumber() {
    return frameNumber;
  }

  /** Sets the sequence number. */
  public void setFrameNumber(long n) {
    frameNumber = n;
  }

  /** How long classification, run-length encoding, merging and statistics took, in nanoseconds. */
  public long processNanos() {
    return processNanos;
  }

  /** Number of blobs on a channel (1..32). */
  public int getNumBlobs(int channel) {
    return count[ChannelBank.checkChannel(channel) - 1];
  }

  /** Total blobs over all channels. */
  public int totalBlobs() {
    int n = 0;
    for (int c : count) {
      n += c;
    }
    return n;
  }

  /** Blob {@code n} (1..count, largest first) of a channel. */
  public Blob getBlob(int channel, int n) {
    int i = index(channel, n);
    return new Blob(area[i], xcg[i], ycg[i], left[i], right[i], top[i], bottom[i], cx[i], cy[i]);
  }

  /** Fills an {@link ArACTSBlob} with blob {@code n} (1..count) of a channel, like ARIA. */
  public void getBlob(int channel, int n, ArACTSBlob blob) {
    int i = index(channel, n);
    blob.setArea(area[i]);
    blob.setXCG(xcg[i]);
    blob.setYCG(ycg[i]);
    blob.setLeft(left[i]);
    blob.setRight(right[i]);
    blob.setTop(top[i]);
    blob.setBottom(bottom[i]);
  }

  /** All blobs of a channel, largest first. */
  public List<Blob> blobs(int channel) {
    int c = getNumBlobs(channel);
    List<Blob> out = new ArrayList<>(c);
    for (int n = 1; n <= c; n++) {
      out.add(getBlob(channel, n));
    }
    return out;
  }

  private int index(int channel, int n) {
    int c = ChannelBank.checkChannel(channel) - 1;
    if (n < 1 || n > count[c]) {
      throw new IndexOutOfBoundsException(
          "blob " + n + " of channel " + channel + ": the channel has " + count[c] + " blobs");
    }
    return c * MAX + n - 1;
  }

  /** Makes this frame empty for an image of the given size. */
  public void clear(int w, int h) {
    width = w;
    height = h;
    processNanos = 0;
    Arrays.fill(count, 0);
  }

  /** Sets blob {@code n} (0-based slot) of channel index {@code c} (0-based). */
  void set(int c, int n, int a, long sumX, long sumY, int l, int r, int t, int b) {
    int i = c * MAX + n;
    area[i] = a;
    xcg[i] = (int) ((2 * sumX + a) / (2L * a));
    ycg[i] = (int) ((2 * sumY + a) / (2L * a));
    left[i] = l;
    right[i] = r;
    top[i] = t;
    bottom[i] = b;
    cx[i] = (double) sumX / a;
    cy[i] = (double) sumY / a;
  }

  /**
   * Sets a channel's blobs directly (used by decoders and tests). Arrays are read from index 0;
   * centroids are taken as exact.
   */
  public void setChannel(
      int channel,
      int n,
      int[] areas,
      int[] xcgs,
      int[] ycgs,
      int[] lefts,
      int[] rights,
      int[] tops,
      int[] bottoms) {
    int c = ChannelBank.checkChannel(channel) - 1;
    if (n < 0 || n > MAX) {
      throw new IllegalArgumentException("a channel has 0.." + MAX + " blobs, got " + n);
    }
    count[c] = n;
    for (int k = 0; k < n; k++) {
      int i = c * MAX + k;
      area[i] = areas[k];
      xcg[i] = xcgs[k];
      ycg[i] = ycgs[k];
      left[i] = lefts[k];
      right[i] = rights[k];
      top[i] = tops[k];
      bottom[i] = bottoms[k];
      cx[i] = xcgs[k];
      cy[i] = ycgs[k];
    }
  }

  /** Copies everything from {@code other}. */
  public void copyFrom(BlobFrame other) {
    width = other.width;
    height = other.height;
    frameNumber = other.frameNumber;
    processNanos = other.processNanos;
    System.arraycopy(other.count, 0, count, 0, CH);
    System.arraycopy(other.area, 0, area, 0, area.length);
    System.arraycopy(other.xcg, 0, xcg, 0, xcg.length);
    System.arraycopy(other.ycg, 0, ycg, 0, ycg.length);
    System.arraycopy(other.left, 0, left, 0, left.length);
    System.arraycopy(other.right, 0, right, 0, right.length);
    System.arraycopy(other.top, 0, top, 0, top.length);
    System.arraycopy(other.bottom, 0, bottom, 0, bottom.length);
    System.arraycopy(other.cx, 0, cx, 0, cx.length);
    System.arraycopy(other.cy, 0, cy, 0, cy.length);
  }

  /** An independent copy. */
  public BlobFrame copy() {
    BlobFrame f = new BlobFrame();
    f.copyFrom(this);
    return f;
  }

  /** A readable summary, one line per channel with blobs (EZ-Train's "Blob stats"). */
  @Override
  public String toString() {
    StringBuilder b = new StringBuilder();
    b.append("frame ").append(frameNumber).append(' ').append(width).append('x').append(height);
    for (int c = 1; c <= CH; c++) {
      for (Blob blob : blobs(c)) {
        b.append(
            String.format(
                java.util.Locale.ROOT,
                "\nchannel %d: a %d x %d y %d l %d r %d t %d b %d",
                c,
                blob.area(),
                blob.xcg(),
                blob.ycg(),
                blob.left(),
                blob.right(),
                blob.top(),
                blob.bottom()));
      }
    }
    return b.toString();
  }
}
