package org.jaria.acts.color;

import java.util.Arrays;

/**
 * One colour channel: what a channel LUT file holds. Three trained {@linkplain ColorPlane planes}
 * (a bit per plane cell) and the manual {@linkplain PlaneLimits limits} of each plane. A pixel is
 * "interesting" to the channel when its projection lies on a trained cell that the limits allow in
 * every plane.
 *
 * <p>A plane is a square of {@code cellsPerAxis × cellsPerAxis} cells; with {@code cellBits = 8}
 * every 8-bit colour value has its own row and column, with fewer bits neighbouring values share a
 * cell (6 bits: 4 values per cell). Coarser cells make the tables small enough to stay in the
 * processor's fastest cache and make training generalise faster, at the price of colour precision;
 * see {@link ChannelBank} for the measured trade-off.
 *
 * <p>A channel is plain data and not thread-safe; the {@link ChannelBank} that owns it serialises
 * access. Colour arguments are 0..255 values; pixels are packed {@code 0xRRGGBB} ints.
 */
public final class Channel {

  /** Smallest supported cell resolution (16 × 16 cells per plane). */
  public static final int MIN_CELL_BITS = 4;

  /** Largest supported cell resolution (256 × 256 cells per plane: one cell per colour value). */
  public static final int MAX_CELL_BITS = 8;

  private static final int PLANES = 3;

  private final int cellBits;
  private final int shift;
  private final int cells;
  private final long[][] trained;
  private final PlaneLimits[] limits = {PlaneLimits.NONE, PlaneLimits.NONE, PlaneLimits.NONE};

  /** An empty (untrained) channel with planes of {@code 2^cellBits} cells per axis. */
  public Channel(int cellBits) {
    checkCellBits(cellBits);
    this.cellBits = cellBits;
    this.shift = 8 - cellBits;
    this.cells = 1 << cellBits;
    this.trained = new long[PLANES][(cells * cells) >>> 6];
  }

  /** Throws if {@code cellBits} is not a supported resolution. */
  static void checkCellBits(int cellBits) {
    if (cellBits < MIN_CELL_BITS || cellBits > MAX_CELL_BITS) {
      throw new IllegalArgumentException(
          "cell resolution must be "
              + MIN_CELL_BITS
              + ".."
              + MAX_CELL_BITS
              + " bits per axis, got "
              + cellBits);
    }
  }

  /** Bits per axis of the planes (cells per axis = {@code 1 << cellBits}). */
  public int cellBits() {
    return cellBits;
  }

  /** Cells per axis of each plane. */
  public int cellsPerAxis() {
    return cells;
  }

  /** The cell (row or column) a colour value 0..255 falls in. */
  public int cellOf(int value) {
    return value >>> shift;
  }

  /** The colour value at the centre of a cell (what the limits are checked against). */
  public int centreOf(int cell) {
    return (cell << shift) + ((1 << shift) >>> 1);
  }

  // ---------------------------------------------------------------- cells

  /** Whether cell {@code (a, b)} of a plane is trained (limits not applied). */
  public boolean isTrained(ColorPlane plane, int a, int b) {
    int i = index(a, b);
    return (trained[plane.ordinal()][i >>> 6] & (1L << i)) != 0;
  }

  /** Whether cell {@code (a, b)} of a plane is trained and allowed by the plane's limits. */
  public boolean isEffective(ColorPlane plane, int a, int b) {
    return isTrained(plane, a, b) && limits[plane.ordinal()].allows(centreOf(a), centreOf(b));
  }

  /** Sets or clears one cell of a plane. */
  public void setCell(ColorPlane plane, int a, int b, boolean on) {
    int i = index(a, b);
    if (on) {
      trained[plane.ordinal()][i >>> 6] |= 1L << i;
    } else {
      trained[plane.ordinal()][i >>> 6] &= ~(1L << i);
    }
  }

  private int index(int a, int b) {
    if (a < 0 || a >= cells || b < 0 || b >= cells) {
      throw new IndexOutOfBoundsException(
          "cell (" + a + ", " + b + ") outside a plane of " + cells + " x " + cells);
    }
    return a * cells + b;
  }

  /** Sets or clears the rectangle of cells {@code [a0, a1] × [b0, b1]} (inclusive, clipped). */
  public void setCells(ColorPlane plane, int a0, int a1, int b0, int b1, boolean on) {
    int lo = Math.max(0, Math.min(a0, a1));
    int hi = Math.min(cells - 1, Math.max(a0, a1));
    int blo = Math.max(0, Math.min(b0, b1));
    int bhi = Math.min(cells - 1, Math.max(b0, b1));
    long[] words = trained[plane.ordinal()];
    for (int a = lo; a <= hi; a++) {
      for (int b = blo; b <= bhi; b++) {
        int i = a * cells + b;
        if (on) {
          words[i >>> 6] |= 1L << i;
        } else {
          words[i >>> 6] &= ~(1L << i);
        }
      }
    }
  }

  // ---------------------------------------------------------------- training

  /**
   * Adds a colour and, in every plane, the square of cells within {@code radius} colour values of
   * it (EZ-Train's Add/Draw; the square makes training robust to small lighting changes).
   *
   * @param rgb packed {@code 0xRRGGBB} colour
   * @param radius neighbourhood half-width in colour values (0 = the colour's own cells only)
   */
  public void addColor(int rgb, int radius) {
    paintColor(rgb, radius, true);
  }

  /** Removes a colour and its neighbourhood square from every plane (EZ-Train's Remove/Erase). */
  public void removeColor(int rgb, int radius) {
    paintColor(rgb, radius, false);
  }

  private void paintColor(int rgb, int radius, boolean on) {
    if (radius < 0) {
      throw new IllegalArgumentException("radius must be >= 0, got " + radius);
    }
    for (ColorPlane p : ColorPlane.all()) {
      int a = p.first(rgb);
      int b = p.second(rgb);
      setCells(
          p,
          cellOf(Math.max(0, a - radius)),
          cellOf(Math.min(255, a + radius)),
          cellOf(Math.max(0, b - radius)),
          cellOf(Math.min(255, b + radius)),
          on);
    }
  }

  /**
   * Adds every colour of the RGB box {@code [r0, r1] × [g0, g1] × [b0, b1]} (inclusive): each plane
   * gets the box's projection. With 8-bit cells the channel then classifies exactly the box (what
   * OpenCV's {@code inRange} does); coarser cells round the box outwards to cell edges.
   */
  public void addRgbBox(int r0, int r1, int g0, int g1, int b0, int b1) {
    checkRange(r0, r1, "red");
    checkRange(g0, g1, "green");
    checkRange(b0, b1, "blue");
    setCells(ColorPlane.RG, cellOf(r0), cellOf(r1), cellOf(g0), cellOf(g1), true);
    setCells(ColorPlane.BG, cellOf(b0), cellOf(b1), cellOf(g0), cellOf(g1), true);
    setCells(ColorPlane.RB, cellOf(r0), cellOf(r1), cellOf(b0), cellOf(b1), true);
  }

  private static void checkRange(int lo, int hi, String name) {
    if (lo < 0 || hi > 255 || lo > hi) {
      throw new IllegalArgumentException(
          name + " range must satisfy 0 <= low <= high <= 255, got " + lo + ".." + hi);
    }
  }

  /** Sets every cell of a plane (manual mode's Fill Plane). */
  public void fillPlane(ColorPlane plane) {
    Arrays.fill(trained[plane.ordinal()], -1L);
  }

  /** Clears every cell of a plane (manual mode's Clear Plane). */
  public void clearPlane(ColorPlane plane) {
    Arrays.fill(trained[plane.ordinal()], 0L);
  }

  /** Clears all three planes and resets the limits (EZ-Train's Clear Training). */
  public void clear() {
    for (long[] words : trained) {
      Arrays.fill(words, 0L);
    }
    resetLimits();
  }

  /** The limits of a plane. */
  public PlaneLimits getLimits(ColorPlane plane) {
    return limits[plane.ordinal()];
  }

  /** Sets the limits of a plane. */
  public void setLimits(ColorPlane plane, PlaneLimits newLimits) {
    if (newLimits == null) {
      throw new IllegalArgumentException("limits must not be null; use PlaneLimits.NONE");
    }
    limits[plane.ordinal()] = newLimits;
  }

  /** Removes the limits of every plane (manual mode's Reset Limits). */
  public void resetLimits() {
    Arrays.fill(limits, PlaneLimits.NONE);
  }

  // ---------------------------------------------------------------- queries

  /**
   * Whether this channel classifies a pixel as interesting. This is the slow reference path (what
   * the {@link LookupTables} compute for all channels at once).
   */
  public boolean classifies(int rgb) {
    for (ColorPlane p : ColorPlane.all()) {
      if (!isEffective(p, cellOf(p.first(rgb)), cellOf(p.second(rgb)))) {
        return false;
      }
    }
    return true;
  }

  /** The number of trained cells of a plane (limits not applied). */
  public int trainedCells(ColorPlane plane) {
    int n = 0;
    for (long w : trained[plane.ordinal()]) {
      n += Long.bitCount(w);
    }
    return n;
  }

  /** Whether no cell of any plane is trained. */
  public boolean isEmpty() {
    for (long[] words : trained) {
      for (long w : words) {
        if (w != 0) {
          return false;
        }
      }
    }
    return true;
  }

  /** Whether this channel has the same resolution, trained cells and limits as {@code other}. */
  public boolean contentEquals(Channel other) {
    if (other.cellBits != cellBits || !Arrays.equals(limits, other.limits)) {
      return false;
    }
    for (int p = 0; p < PLANES; p++) {
      if (!Arrays.equals(trained[p], other.trained[p])) {
        return false;
      }
    }
    return true;
  }

  /** An independent copy. */
  public Channel copy() {
    Channel c = new Channel(cellBits);
    c.copyFrom(this);
    return c;
  }

  /** Makes this channel equal to {@code other}, which must have the same resolution. */
  public void copyFrom(Channel other) {
    if (other.cellBits != cellBits) {
      throw new IllegalArgumentException(
          "cannot copy a "
              + other.cellBits
              + "-bit channel into a "
              + cellBits
              + "-bit one; use resampled()");
    }
    for (int p = 0; p < PLANES; p++) {
      System.arraycopy(other.trained[p], 0, trained[p], 0, trained[p].length);
    }
    System.arraycopy(other.limits, 0, limits, 0, PLANES);
  }

  /**
   * This channel at another resolution. Going coarser, a cell is set when any of the finer cells it
   * covers is; going finer, every fine cell takes its coarse cell's value. Limits carry over.
   */
  public Channel resampled(int newCellBits) {
    Channel out = new Channel(newCellBits);
    System.arraycopy(limits, 0, out.limits, 0, PLANES);
    int n = out.cells;
    for (ColorPlane p : ColorPlane.all()) {
      if (newCellBits <= cellBits) {
        int d = cellBits - newCellBits;
        for (int a = 0; a < cells; a++) {
          for (int b = 0; b < cells; b++) {
            if (isTrained(p, a, b)) {
              out.setCell(p, a >>> d, b >>> d, true);
            }
          }
        }
      } else {
        int d = newCellBits - cellBits;
        for (int a = 0; a < n; a++) {
          for (int b = 0; b < n; b++) {
            if (isTrained(p, a >>> d, b >>> d)) {
              out.setCell(p, a, b, true);
            }
          }
        }
      }
    }
    return out;
  }

  // ---------------------------------------------------------------- package internals

  /** The raw trained bits of a plane (cell {@code (a, b)} is bit {@code a * cells + b}). */
  long[] words(ColorPlane plane) {
    return trained[plane.ordinal()];
  }

  /**
   * Writes this channel's effective cells of a plane into bit {@code bit} of a classification table
   * (one int per cell, indexed like the trained bits).
   *
   * @return whether any cell of the plane is effective
   */
  boolean compileInto(ColorPlane plane, int[] table, int bit) {
    long[] words = trained[plane.ordinal()];
    PlaneLimits lim = limits[plane.ordinal()];
    boolean noLimits = lim.isNone();
    int mask = 1 << bit;
    int keep = ~mask;
    boolean any = false;
    for (int i = 0; i < table.length; i++) {
      boolean on = (words[i >>> 6] & (1L << i)) != 0;
      if (on && !noLimits) {
        on = lim.allows(centreOf(i >>> cellBits), centreOf(i & (cells - 1)));
      }
      table[i] = on ? (table[i] | mask) : (table[i] & keep);
      any |= on;
    }
    return any;
  }
}
