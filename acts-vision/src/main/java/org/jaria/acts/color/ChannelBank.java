package org.jaria.acts.color;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.function.Function;

/**
 * The 32 colour channels of an ACTS server, with each channel's tracked-blob count and file name,
 * and the compiled {@link LookupTables} that classify pixels for all channels at once.
 *
 * <p>Channels are numbered 1..32 as in ACTS and ARIA. Editing goes through {@link #edit}; every
 * edit updates the channel's bit in the live tables and bumps {@link #version()}. {@link #tables()}
 * returns an immutable snapshot, recompiled only after an edit, so a tracker thread can classify
 * frames while a training user interface edits channels on another thread.
 *
 * <h2>Plane resolution</h2>
 *
 * <p>The resolution is fixed per bank ({@code cellBits} per axis); {@value #DEFAULT_CELL_BITS} bits
 * (256 × 256 cells, one per colour value) is the default, chosen by measurement. With 256 cells a
 * pixel's three table indices are byte pairs of the packed pixel, so classification needs no
 * per-component shifts; with fewer cells every component must be shifted and recombined. Measured
 * on one core of the development machine (Xeon, JDK 17) with {@code VisionBenchmark} (desk scene,
 * 640×480, 8 channels, whole tracker), a frame took 0.67 ms with 256 × 256 cells, 0.99 ms with 128
 * × 128 and 1.03 ms with 64 × 64; on uniformly random noise, where the small tables' better cache
 * fit should help most, all three took the same 3.3–3.4 ms. The price of 256 cells is memory: 768
 * KB of tables (48 KB at 64 × 64) and 24 KB per channel file (1.5 KB). Full resolution also keeps
 * colour precision, and makes an RGB box channel classify exactly what OpenCV's {@code inRange}
 * does. Coarser cells generalise faster when training from few pixels (each trained colour covers
 * its neighbours); Add's neighbourhood square gives much the same effect at full resolution.
 *
 * <p>Thread-safe.
 */
public final class ChannelBank {

  /** Number of channels (ACTS's 32). */
  public static final int NUM_CHANNELS = 32;

  /** Most blobs a channel can report (ACTS's 10). */
  public static final int MAX_TRACKED_BLOBS = 10;

  /** Blobs a channel reports unless told otherwise (ACTS's 3). */
  public static final int DEFAULT_TRACKED_BLOBS = 3;

  /** The default plane resolution in bits per axis (see the class comment). */
  public static final int DEFAULT_CELL_BITS = 8;

  private final int cellBits;

  // The arrays' contents change: every access holds the bank's monitor.
  @GuardedBy("this")
  private final Channel[] channels = new Channel[NUM_CHANNELS];

  @GuardedBy("this")
  private final int[] trackedBlobs = new int[NUM_CHANNELS];

  @GuardedBy("this")
  private final String[] fileNames = new String[NUM_CHANNELS];

  @GuardedBy("this")
  private final int[][] live;

  @GuardedBy("this")
  private int activeMask;

  @GuardedBy("this")
  private long version;

  @GuardedBy("this")
  private LookupTables cached;

  /** A bank of empty channels at the default resolution. */
  public ChannelBank() {
    this(DEFAULT_CELL_BITS);
  }

  /** A bank of empty channels with planes of {@code 2^cellBits} cells per axis (4..8). */
  public ChannelBank(int cellBits) {
    Channel.checkCellBits(cellBits);
    this.cellBits = cellBits;
    int cells = 1 << (2 * cellBits);
    live = new int[][] {new int[cells], new int[cells], new int[cells]};
    for (int i = 0; i < NUM_CHANNELS; i++) {
      channels[i] = new Channel(cellBits);
      trackedBlobs[i] = DEFAULT_TRACKED_BLOBS;
      fileNames[i] = defaultFileName(i + 1);
    }
  }

  /** ACTS's default file name of a channel: {@code channelN.lut}. */
  public static String defaultFileName(int channel) {
    return "channel" + checkChannel(channel) + ".lut";
  }

  /** Returns {@code channel} if it is 1..32, else throws. */
  public static int checkChannel(int channel) {
    if (channel < 1 || channel > NUM_CHANNELS) {
      throw new IllegalArgumentException("channel must be 1.." + NUM_CHANNELS + ", got " + channel);
    }
    return channel;
  }

  /** Bits per axis of every channel's planes. */
  public int cellBits() {
    return cellBits;
  }

  /** Increases on every change; a {@link LookupTables} snapshot carries the version it saw. */
  public synchronized long version() {
    return version;
  }

  /** A copy of a channel's current contents. */
  public synchronized Channel copyOf(int channel) {
    return channels[checkChannel(channel) - 1].copy();
  }

  /**
   * Runs {@code editor} on a channel with the bank locked, then recompiles the channel. The editor
   * must not keep the channel reference after returning.
   *
   * @return what the editor returned
   */
  public synchronized <T> T edit(int channel, Function<Channel, T> editor) {
    int i = checkChannel(channel) - 1;
    try {
      return editor.apply(channels[i]);
    } finally {
      recompile(i);
      version++;
    }
  }

  /** Replaces a channel's contents with (a copy of) {@code contents}, resampled if needed. */
  public synchronized void replace(int channel, Channel contents) {
    int i = checkChannel(channel) - 1;
    channels[i].copyFrom(contents.cellBits() == cellBits ? contents : contents.resampled(cellBits));
    recompile(i);
    version++;
  }

  /**
   * Replaces every channel at once (loading a runtime configuration): either all of it happens or,
   * if an argument is invalid, nothing does.
   *
   * @param contents 32 channels; a null entry means an empty channel
   * @param tracked 32 tracked-blob counts (1..10)
   * @param names 32 file names; a null entry means the default name
   */
  public synchronized void replaceAll(Channel[] contents, int[] tracked, String[] names) {
    if (contents.length != NUM_CHANNELS
        || tracked.length != NUM_CHANNELS
        || names.length != NUM_CHANNELS) {
      throw new IllegalArgumentException("replaceAll needs 32 entries in each array");
    }
    for (int t : tracked) {
      checkTracked(t);
    }
    Channel[] prepared = new Channel[NUM_CHANNELS];
    for (int i = 0; i < NUM_CHANNELS; i++) {
      Channel c = contents[i];
      prepared[i] =
          c == null ? new Channel(cellBits) : c.cellBits() == cellBits ? c : c.resampled(cellBits);
    }
    for (int i = 0; i < NUM_CHANNELS; i++) {
      channels[i].copyFrom(prepared[i]);
      trackedBlobs[i] = tracked[i];
      fileNames[i] = names[i] == null ? defaultFileName(i + 1) : names[i];
      recompile(i);
    }
    version++;
  }

  /** How many blobs a channel reports (1..10, default 3). */
  public synchronized int getTrackedBlobs(int channel) {
    return trackedBlobs[checkChannel(channel) - 1];
  }

  /** Sets how many blobs a channel reports (1..10). */
  public synchronized void setTrackedBlobs(int channel, int count) {
    trackedBlobs[checkChannel(channel) - 1] = checkTracked(count);
    version++;
  }

  private static int checkTracked(int count) {
    if (count < 1 || count > MAX_TRACKED_BLOBS) {
      throw new IllegalArgumentException(
          "tracked blobs must be 1.." + MAX_TRACKED_BLOBS + ", got " + count);
    }
    return count;
  }

  /** The channel's file name (default {@code channelN.lut}). */
  public synchronized String getFileName(int channel) {
    return fileNames[checkChannel(channel) - 1];
  }

  /** Sets the channel's file name. */
  public synchronized void setFileName(int channel, String name) {
    if (name == null || name.isBlank()) {
      throw new IllegalArgumentException("a channel file name must not be empty");
    }
    fileNames[checkChannel(channel) - 1] = name;
  }

  /** The channels that can classify anything (bit {@code c} = channel {@code c + 1}). */
  public synchronized int activeMask() {
    return activeMask;
  }

  /** The compiled tables of the current state (recompiled only after a change). */
  public synchronized LookupTables tables() {
    if (cached == null || cached.version() != version) {
      cached =
          new LookupTables(
              cellBits,
              live[0].clone(),
              live[1].clone(),
              live[2].clone(),
              activeMask,
              trackedBlobs.clone(),
              version);
    }
    return cached;
  }

  @GuardedBy("this")
  private void recompile(int i) {
    boolean all = true;
    for (ColorPlane p : ColorPlane.all()) {
      all &= channels[i].compileInto(p, live[p.ordinal()], i);
    }
    activeMask = all ? (activeMask | (1 << i)) : (activeMask & ~(1 << i));
  }
}
