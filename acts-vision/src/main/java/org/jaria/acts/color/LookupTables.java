package org.jaria.acts.color;

/**
 * An immutable, compiled snapshot of a {@link ChannelBank}: the three plane tables that classify a
 * pixel for all 32 channels at once (CMVision's trick, which ACTS uses). Each table has one int per
 * plane cell whose bit {@code c} says whether channel {@code c + 1} wants that cell; a pixel's
 * channel mask is
 *
 * <pre>rg[cell(R), cell(G)] &amp; bg[cell(B), cell(G)] &amp; rb[cell(R), cell(B)]</pre>
 *
 * <p>— one lookup per plane and two ANDs per pixel, whatever the number of channels. Also carries
 * each channel's tracked-blob count so that one snapshot describes a frame's whole configuration.
 *
 * <p>Safe to share between threads: nothing in it changes after construction.
 */
public final class LookupTables {

  private final int cellBits;
  private final int[] rg;
  private final int[] bg;
  private final int[] rb;
  private final int activeMask;
  private final int[] trackedBlobs;
  private final long version;

  LookupTables(
      int cellBits,
      int[] rg,
      int[] bg,
      int[] rb,
      int activeMask,
      int[] trackedBlobs,
      long version) {
    this.cellBits = cellBits;
    this.rg = rg;
    this.bg = bg;
    this.rb = rb;
    this.activeMask = activeMask;
    this.trackedBlobs = trackedBlobs;
    this.version = version;
  }

  /** Bits per axis of the plane tables. */
  public int cellBits() {
    return cellBits;
  }

  /**
   * The channels that can classify anything (bit {@code c} = channel {@code c + 1}): every plane
   * has at least one effective cell.
   */
  public int activeMask() {
    return activeMask;
  }

  /** How many blobs channel {@code channel} (1..32) reports. */
  public int trackedBlobs(int channel) {
    return trackedBlobs[ChannelBank.checkChannel(channel) - 1];
  }

  /** The {@link ChannelBank#version()} this snapshot was compiled from. */
  public long version() {
    return version;
  }

  /** The channel mask of one packed {@code 0xRRGGBB} pixel. */
  public int classify(int rgb) {
    int s = 8 - cellBits;
    int r = ((rgb >>> 16) & 0xFF) >>> s;
    int g = ((rgb >>> 8) & 0xFF) >>> s;
    int b = (rgb & 0xFF) >>> s;
    return rg[(r << cellBits) | g] & bg[(b << cellBits) | g] & rb[(r << cellBits) | b];
  }

  /** Classifies {@code n} pixels of {@code rgb} into {@code masks} (a mask image for displays). */
  public void classify(int[] rgb, int[] masks, int n) {
    for (int i = 0; i < n; i++) {
      masks[i] = classify(rgb[i]);
    }
  }

  /**
   * Classifies a frame and run-length encodes it in one pass: the hot path of the tracker.
   *
   * @param rgb packed {@code 0xRRGGBB} pixels, row by row, at least {@code width * height}
   * @param width frame width
   * @param height frame height
   * @param out receives the runs (its buffers are reused and grow if needed)
   */
  public void encodeRuns(int[] rgb, int width, int height, MaskRuns out) {
    if (rgb.length < width * height) {
      throw new IllegalArgumentException(
          "frame has " + rgb.length + " pixels, fewer than " + width + "x" + height);
    }
    out.reset(width, height);
    if (cellBits == 8) {
      encode8(rgb, width, height, out);
    } else {
      encodeQuantised(rgb, width, height, out);
    }
  }

  // With 8-bit cells the table indices are byte pairs of the packed pixel: no per-component shifts.
  private void encode8(int[] rgb, int width, int height, MaskRuns out) {
    int[] trg = rg;
    int[] tbg = bg;
    int[] trb = rb;
    int seen = 0;
    int n = 0;
    for (int y = 0; y < height; y++) {
      out.rowStart[y] = n;
      out.count = n;
      out.ensureFree(width);
      int[] ox0 = out.x0;
      int[] ox1 = out.x1;
      int[] om = out.mask;
      int base = y * width;
      int prev = 0;
      int start = 0;
      for (int x = 0; x < width; x++) {
        int p = rgb[base + x];
        int m =
            trg[(p >>> 8) & 0xFFFF]
                & tbg[((p & 0xFF) << 8) | ((p >>> 8) & 0xFF)]
                & trb[((p >>> 8) & 0xFF00) | (p & 0xFF)];
        if (m != prev) {
          if (prev != 0) {
            ox0[n] = start;
            ox1[n] = x - 1;
            om[n] = prev;
            n++;
            seen |= prev;
          }
          prev = m;
          start = x;
        }
      }
      if (prev != 0) {
        ox0[n] = start;
        ox1[n] = width - 1;
        om[n] = prev;
        n++;
        seen |= prev;
      }
    }
    out.rowStart[height] = n;
    out.count = n;
    out.seen = seen;
  }

  private void encodeQuantised(int[] rgb, int width, int height, MaskRuns out) {
    int[] trg = rg;
    int[] tbg = bg;
    int[] trb = rb;
    int q = cellBits;
    int s = 8 - q;
    int seen = 0;
    int n = 0;
    for (int y = 0; y < height; y++) {
      out.rowStart[y] = n;
      out.count = n;
      out.ensureFree(width);
      int[] ox0 = out.x0;
      int[] ox1 = out.x1;
      int[] om = out.mask;
      int base = y * width;
      int prev = 0;
      int start = 0;
      for (int x = 0; x < width; x++) {
        int p = rgb[base + x];
        int r = ((p >>> 16) & 0xFF) >>> s;
        int g = ((p >>> 8) & 0xFF) >>> s;
        int b = (p & 0xFF) >>> s;
        int m = trg[(r << q) | g] & tbg[(b << q) | g] & trb[(r << q) | b];
        if (m != prev) {
          if (prev != 0) {
            ox0[n] = start;
            ox1[n] = x - 1;
            om[n] = prev;
            n++;
            seen |= prev;
          }
          prev = m;
          start = x;
        }
      }
      if (prev != 0) {
        ox0[n] = start;
        ox1[n] = width - 1;
        om[n] = prev;
        n++;
        seen |= prev;
      }
    }
    out.rowStart[height] = n;
    out.count = n;
    out.seen = seen;
  }
}
