package org.jaria.sim.world;

import java.util.Arrays;

/**
 * A uniform grid over the static obstacles of a world (map lines, map points as small discs,
 * injected obstacles): what makes a sonar or laser ray cost about the same whether the map has a
 * hundred lines or a hundred thousand.
 *
 * <p>The grid is stored as primitive arrays in compressed-row form (for each cell, a run of
 * primitive indices). A ray walks the cells it crosses in order (Amanatides–Woo) and stops as soon
 * as the nearest hit found lies before the exit of the current cell, so its cost depends on the
 * local clutter and the distance to the first hit, not on the size of the map. A primitive that
 * spans several cells is tested once per query thanks to a per-primitive stamp.
 *
 * <p>Immutable once built, but the query methods use a shared stamp array: one thread queries at a
 * time (the world thread).
 */
public final class SegmentIndex {

  private static final byte SHAPE_SEGMENT = 0;
  private static final byte SHAPE_DISC = 1;
  private static final RayHit.HitKind[] KINDS = RayHit.HitKind.values();

  /** Cells are at least this big, mm. */
  static final double MIN_CELL = 100;

  /** Cells are at most this big, mm. */
  static final double MAX_CELL = 2000;

  private static final long MAX_CELLS = 1 << 22;

  /** Cell bounds are capped here, far above any budget, so their sums cannot overflow. */
  private static final double BOUND_CAP = 1e15;

  private final int count;
  private final byte[] shape;
  private final byte[] kind;
  private final double[] ax;
  private final double[] ay;
  private final double[] bx;
  private final double[] by;
  private final double minX;
  private final double minY;
  private final double maxX;
  private final double maxY;
  private final double cell;
  private final double invCell;
  private final int nx;
  private final int ny;
  private final int[] cellStart;
  private final int[] cellItems;
  private final int[] stamp;
  private final double[] clip = new double[2];
  private int currentStamp;

  private SegmentIndex(Builder b, double cellHint) {
    count = b.n;
    shape = Arrays.copyOf(b.shape, count);
    kind = Arrays.copyOf(b.kind, count);
    ax = Arrays.copyOf(b.ax, count);
    ay = Arrays.copyOf(b.ay, count);
    bx = Arrays.copyOf(b.bx, count);
    by = Arrays.copyOf(b.by, count);
    stamp = new int[count];
    double x0 = Double.POSITIVE_INFINITY;
    double y0 = Double.POSITIVE_INFINITY;
    double x1 = Double.NEGATIVE_INFINITY;
    double y1 = Double.NEGATIVE_INFINITY;
    for (int i = 0; i < count; i++) {
      double r = shape[i] == SHAPE_DISC ? bx[i] : 0;
      double qx = shape[i] == SHAPE_DISC ? ax[i] : Math.min(ax[i], bx[i]);
      double qy = shape[i] == SHAPE_DISC ? ay[i] : Math.min(ay[i], by[i]);
      double rx = shape[i] == SHAPE_DISC ? ax[i] : Math.max(ax[i], bx[i]);
      double ry = shape[i] == SHAPE_DISC ? ay[i] : Math.max(ay[i], by[i]);
      x0 = Math.min(x0, qx - r);
      y0 = Math.min(y0, qy - r);
      x1 = Math.max(x1, rx + r);
      y1 = Math.max(y1, ry + r);
    }
    if (count == 0) {
      x0 = y0 = 0;
      x1 = y1 = 1;
    }
    minX = x0 - 1;
    minY = y0 - 1;
    maxX = x1 + 1;
    maxY = y1 + 1;
    double c = cellFor(maxX - minX, maxY - minY, count, cellHint);
    cell = c;
    invCell = 1 / c;
    nx = Math.max(1, (int) Math.ceil((maxX - minX) / c));
    ny = Math.max(1, (int) Math.ceil((maxY - minY) / c));
    cellStart = new int[nx * ny + 1];
    for (int i = 0; i < count; i++) {
      visitCells(i, null);
    }
    int total = 0;
    for (int k = 0; k < nx * ny; k++) {
      int n = cellStart[k];
      cellStart[k] = total;
      if (n > Integer.MAX_VALUE - total) {
        throw new IllegalStateException(
            "the index would hold more than "
                + Integer.MAX_VALUE
                + " cell entries; check the map"
                + " against MapBudget before building a world on it");
      }
      total += n;
    }
    cellStart[nx * ny] = total;
    cellItems = new int[total];
    int[] fill = Arrays.copyOf(cellStart, nx * ny);
    for (int i = 0; i < count; i++) {
      visitCells(i, fill);
    }
  }

  private static double autoCell(double w, double h, int n) {
    double c = 2 * Math.sqrt(w * h / Math.max(1, n));
    return Math.max(MIN_CELL, Math.min(MAX_CELL, c));
  }

  /**
   * The cell edge an index picks for {@code count} primitives over a {@code w} × {@code h} mm
   * extent (the given {@code hint} if positive), grown until the grid has at most {@link
   * #MAX_CELLS} cells.
   */
  static double cellFor(double w, double h, int count, double hint) {
    double c = hint > 0 ? hint : autoCell(w, h, count);
    while ((long) Math.ceil(w / c) * (long) Math.ceil(h / c) > MAX_CELLS) {
      c *= 1.5;
    }
    return c;
  }

  /**
   * At most how many grid cells a segment from (x1, y1) to (x2, y2) is recorded in, with cells of
   * edge {@code cell}: the index records it row by row, at most two cells more per row than its run
   * across the row.
   */
  static long segmentCellsBound(double x1, double y1, double x2, double y2, double cell) {
    double cols = Math.ceil(Math.abs(x2 - x1) / cell);
    double rows = Math.floor(Math.abs(y2 - y1) / cell) + 2;
    return (long) Math.min(cols + 2 * rows + 1, BOUND_CAP);
  }

  /** At most how many grid cells a disc of radius {@code r} is recorded in. */
  static long discCellsBound(double r, double cell) {
    double side = Math.floor(2 * r / cell) + 2;
    return (long) Math.min(side * side, BOUND_CAP);
  }

  /** A builder collecting primitives. */
  public static Builder builder() {
    return new Builder();
  }

  /** How many primitives the index holds. */
  public int size() {
    return count;
  }

  /** Edge length of one grid cell, mm. */
  public double cellSize() {
    return cell;
  }

  /** Number of grid cells. */
  public int cellCount() {
    return nx * ny;
  }

  /** How many (cell, primitive) entries the grid holds: what the index costs beyond its shapes. */
  public int cellEntries() {
    return cellItems.length;
  }

  private int cellX(double x) {
    int i = (int) Math.floor((x - minX) * invCell);
    return i < 0 ? 0 : (i >= nx ? nx - 1 : i);
  }

  private int cellY(double y) {
    int i = (int) Math.floor((y - minY) * invCell);
    return i < 0 ? 0 : (i >= ny ? ny - 1 : i);
  }

  /**
   * Counts (fill == null) or records (fill != null) primitive {@code i} in every cell it touches.
   */
  private void visitCells(int i, int[] fill) {
    double eps = cell * 1e-6;
    if (shape[i] == SHAPE_DISC) {
      double r = bx[i] + eps;
      int ix0 = cellX(ax[i] - r);
      int ix1 = cellX(ax[i] + r);
      int iy0 = cellY(ay[i] - r);
      int iy1 = cellY(ay[i] + r);
      for (int iy = iy0; iy <= iy1; iy++) {
        for (int ix = ix0; ix <= ix1; ix++) {
          record(iy * nx + ix, i, fill);
        }
      }
      return;
    }
    double x1 = ax[i];
    double y1 = ay[i];
    double x2 = bx[i];
    double y2 = by[i];
    int iy0 = cellY(Math.min(y1, y2) - eps);
    int iy1 = cellY(Math.max(y1, y2) + eps);
    for (int iy = iy0; iy <= iy1; iy++) {
      double lo = minY + iy * cell - eps;
      double hi = lo + cell + 2 * eps;
      double xa;
      double xb;
      if (y2 == y1) {
        xa = Math.min(x1, x2);
        xb = Math.max(x1, x2);
      } else {
        double ta = (lo - y1) / (y2 - y1);
        double tb = (hi - y1) / (y2 - y1);
        double t0 = Math.max(0, Math.min(ta, tb));
        double t1 = Math.min(1, Math.max(ta, tb));
        if (t0 > t1) {
          continue;
        }
        double xa0 = x1 + t0 * (x2 - x1);
        double xb0 = x1 + t1 * (x2 - x1);
        xa = Math.min(xa0, xb0);
        xb = Math.max(xa0, xb0);
      }
      int ix0 = cellX(xa - eps);
      int ix1 = cellX(xb + eps);
      for (int ix = ix0; ix <= ix1; ix++) {
        record(iy * nx + ix, i, fill);
      }
    }
  }

  private void record(int cellIndex, int item, int[] fill) {
    if (fill == null) {
      cellStart[cellIndex]++;
    } else {
      cellItems[fill[cellIndex]++] = item;
    }
  }

  private int nextStamp() {
    if (++currentStamp == Integer.MAX_VALUE) {
      Arrays.fill(stamp, 0);
      currentStamp = 1;
    }
    return currentStamp;
  }

  /**
   * Casts a ray from (ox, oy) along the unit direction (dx, dy) up to {@code maxRange} and records
   * the nearest hit in {@code out} if it is nearer than what {@code out} already holds (so a caller
   * can combine this index with other obstacles). Allocates nothing.
   *
   * @return whether this index improved {@code out}
   */
  public boolean cast(double ox, double oy, double dx, double dy, double maxRange, RayHit out) {
    if (count == 0) {
      return false;
    }
    double limit = Math.min(maxRange, out.distance);
    double t0 = 0;
    double t1 = limit;
    if (dx != 0) {
      double ta = (minX - ox) / dx;
      double tb = (maxX - ox) / dx;
      t0 = Math.max(t0, Math.min(ta, tb));
      t1 = Math.min(t1, Math.max(ta, tb));
    } else if (ox < minX || ox > maxX) {
      return false;
    }
    if (dy != 0) {
      double ta = (minY - oy) / dy;
      double tb = (maxY - oy) / dy;
      t0 = Math.max(t0, Math.min(ta, tb));
      t1 = Math.min(t1, Math.max(ta, tb));
    } else if (oy < minY || oy > maxY) {
      return false;
    }
    if (t0 > t1) {
      return false;
    }
    int ix = cellX(ox + t0 * dx);
    int iy = cellY(oy + t0 * dy);
    int stepX = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
    int stepY = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
    double tMaxX =
        dx > 0
            ? (minX + (ix + 1) * cell - ox) / dx
            : (dx < 0 ? (minX + ix * cell - ox) / dx : Double.POSITIVE_INFINITY);
    double tMaxY =
        dy > 0
            ? (minY + (iy + 1) * cell - oy) / dy
            : (dy < 0 ? (minY + iy * cell - oy) / dy : Double.POSITIVE_INFINITY);
    double tDeltaX = dx != 0 ? cell / Math.abs(dx) : Double.POSITIVE_INFINITY;
    double tDeltaY = dy != 0 ? cell / Math.abs(dy) : Double.POSITIVE_INFINITY;
    int s = nextStamp();
    double best = limit;
    int bestItem = -1;
    while (true) {
      int c = iy * nx + ix;
      for (int k = cellStart[c], end = cellStart[c + 1]; k < end; k++) {
        int item = cellItems[k];
        if (stamp[item] == s) {
          continue;
        }
        stamp[item] = s;
        double t =
            shape[item] == SHAPE_DISC
                ? Geometry2d.rayDisc(ox, oy, dx, dy, ax[item], ay[item], bx[item])
                : Geometry2d.raySegment(ox, oy, dx, dy, ax[item], ay[item], bx[item], by[item]);
        if (t <= best) {
          best = t;
          bestItem = item;
        }
      }
      double tExit = Math.min(tMaxX, tMaxY);
      if (best <= tExit || tExit > t1) {
        break;
      }
      if (tMaxX < tMaxY) {
        ix += stepX;
        tMaxX += tDeltaX;
        if (ix < 0 || ix >= nx) {
          break;
        }
      } else {
        iy += stepY;
        tMaxY += tDeltaY;
        if (iy < 0 || iy >= ny) {
          break;
        }
      }
    }
    if (bestItem < 0 || best >= out.distance) {
      return false;
    }
    out.distance = best;
    out.kind = KINDS[kind[bestItem]];
    out.robot = -1;
    if (shape[bestItem] == SHAPE_DISC) {
      double hx = ox + best * dx - ax[bestItem];
      double hy = oy + best * dy - ay[bestItem];
      double len = Math.sqrt(hx * hx + hy * hy);
      out.cosIncidence = len == 0 ? 1 : Math.abs(hx * dx + hy * dy) / len;
    } else {
      out.cosIncidence =
          Geometry2d.cosIncidenceSegment(
              dx, dy, ax[bestItem], ay[bestItem], bx[bestItem], by[bestItem]);
    }
    return true;
  }

  /**
   * Finds what the convex CCW polygon ({@code px}, {@code py}, {@code n} vertices) overlaps and
   * offers each contact point (the middle of the part of a wall inside the polygon, or a point's
   * centre) to {@code out}, which keeps the one nearest to (cx, cy).
   *
   * @return whether anything in this index overlaps the polygon
   */
  public boolean findContacts(double[] px, double[] py, int n, double cx, double cy, Contact out) {
    if (count == 0) {
      return false;
    }
    double x0 = Double.POSITIVE_INFINITY;
    double y0 = Double.POSITIVE_INFINITY;
    double x1 = Double.NEGATIVE_INFINITY;
    double y1 = Double.NEGATIVE_INFINITY;
    for (int i = 0; i < n; i++) {
      x0 = Math.min(x0, px[i]);
      y0 = Math.min(y0, py[i]);
      x1 = Math.max(x1, px[i]);
      y1 = Math.max(y1, py[i]);
    }
    if (x1 < minX || x0 > maxX || y1 < minY || y0 > maxY) {
      return false;
    }
    int s = nextStamp();
    boolean any = false;
    int ix0 = cellX(x0);
    int ix1 = cellX(x1);
    int iy0 = cellY(y0);
    int iy1 = cellY(y1);
    for (int iy = iy0; iy <= iy1; iy++) {
      for (int ix = ix0; ix <= ix1; ix++) {
        int c = iy * nx + ix;
        for (int k = cellStart[c], end = cellStart[c + 1]; k < end; k++) {
          int item = cellItems[k];
          if (stamp[item] == s) {
            continue;
          }
          stamp[item] = s;
          if (shape[item] == SHAPE_DISC) {
            if (Geometry2d.discOverlapsConvex(ax[item], ay[item], bx[item], px, py, n)) {
              any = true;
              out.offer(ax[item], ay[item], cx, cy, KINDS[kind[item]], -1);
            }
          } else if (Geometry2d.clipSegmentConvex(
              ax[item], ay[item], bx[item], by[item], px, py, n, clip)) {
            // The contact is the middle of the part of the wall inside the footprint: a wall met
            // head on touches mid-front, one met at an angle touches the corner it reaches.
            any = true;
            double t = (clip[0] + clip[1]) / 2;
            out.offer(
                ax[item] + t * (bx[item] - ax[item]),
                ay[item] + t * (by[item] - ay[item]),
                cx,
                cy,
                KINDS[kind[item]],
                -1);
          }
        }
      }
    }
    return any;
  }

  /** Collects primitives for a {@link SegmentIndex}. Not thread-safe. */
  public static final class Builder {
    private int n;
    private byte[] shape = new byte[64];
    private byte[] kind = new byte[64];
    private double[] ax = new double[64];
    private double[] ay = new double[64];
    private double[] bx = new double[64];
    private double[] by = new double[64];

    private Builder() {}

    private void grow() {
      if (n == shape.length) {
        int cap = shape.length * 2;
        shape = Arrays.copyOf(shape, cap);
        kind = Arrays.copyOf(kind, cap);
        ax = Arrays.copyOf(ax, cap);
        ay = Arrays.copyOf(ay, cap);
        bx = Arrays.copyOf(bx, cap);
        by = Arrays.copyOf(by, cap);
      }
    }

    /** Adds a wall segment of the given kind (a map line or an injected obstacle). */
    public Builder addSegment(double x1, double y1, double x2, double y2, RayHit.HitKind k) {
      grow();
      shape[n] = SHAPE_SEGMENT;
      kind[n] = (byte) k.ordinal();
      ax[n] = x1;
      ay[n] = y1;
      bx[n] = x2;
      by[n] = y2;
      n++;
      return this;
    }

    /** Adds a small round obstacle (a map point) of radius {@code r}. */
    public Builder addDisc(double x, double y, double r, RayHit.HitKind k) {
      grow();
      shape[n] = SHAPE_DISC;
      kind[n] = (byte) k.ordinal();
      ax[n] = x;
      ay[n] = y;
      bx[n] = r;
      by[n] = 0;
      n++;
      return this;
    }

    /** How many primitives were added. */
    public int size() {
      return n;
    }

    /** Builds the index with a cell size chosen from the extent and the number of primitives. */
    public SegmentIndex build() {
      return new SegmentIndex(this, 0);
    }

    /** Builds the index with the given cell size, mm. */
    public SegmentIndex build(double cellSize) {
      if (!(cellSize > 0)) {
        throw new IllegalArgumentException("cell size must be positive, was " + cellSize);
      }
      return new SegmentIndex(this, cellSize);
    }
  }
}
