package org.jaria.mapping;

import java.util.Arrays;

/**
 * Reference points bucketed in a uniform grid for nearest-neighbour look-ups: what a scan is
 * matched against. Points are added in the map frame; a point closer than {@link #DEDUP_MM} to one
 * already there is skipped, so overlapping scans of the same wall do not pile up. {@link #build()}
 * also lets each point's surface normal be estimated (when first asked for) from its neighbours
 * within {@link #NORMAL_RADIUS_MM} (a line fitted through them, so the many scans of a wall give a
 * steady normal). Where they do not lie on a line (a corner) {@link #nx} is NaN and the point is
 * matched point to point; a point with too few neighbours (far along a wall, where the readings are
 * sparse) takes the normal of the line to its nearest neighbour, as its position along the wall is
 * mere sampling; with none within half a metre it has NaN for both and is not matched. Built anew
 * for each match from primitive arrays that are reused, so a build allocates nothing once the
 * arrays have grown.
 *
 * <p>Not thread-safe.
 */
final class PointIndex {

  /** Points closer than this to an earlier one are not added, mm. */
  static final double DEDUP_MM = 25;

  /** Neighbours within this estimate a point's normal, mm. */
  static final double NORMAL_RADIUS_MM = 150;

  private static final double CELL = 150;
  private static final int MAX_CELLS = 4_000_000;

  private double[] px = new double[4096];
  private double[] py = new double[4096];
  private double[] pnx = new double[4096];
  private double[] pny = new double[4096];
  private boolean[] hasNormal = new boolean[4096];
  private int n;
  private final CellCounts dedup = new CellCounts(8192);

  private double minX;
  private double minY;
  private double cell = CELL;
  private int gw;
  private int gh;
  private int[] start = new int[1];
  private int[] items = new int[0];

  /** Empties the index. */
  void clear() {
    n = 0;
    dedup.clear();
    gw = 0;
    gh = 0;
  }

  /** Adds a point (map frame, mm), unless one lies within 25 mm. */
  void add(double x, double y) {
    int cx = (int) Math.floor(x / DEDUP_MM);
    int cy = (int) Math.floor(y / DEDUP_MM);
    if (dedup.add(cx, cy, 1) > 0) {
      return;
    }
    if (n == px.length) {
      px = Arrays.copyOf(px, n * 2);
      py = Arrays.copyOf(py, n * 2);
      pnx = Arrays.copyOf(pnx, n * 2);
      pny = Arrays.copyOf(pny, n * 2);
    }
    px[n] = x;
    py[n] = y;
    n++;
  }

  int size() {
    return n;
  }

  double x(int i) {
    return px[i];
  }

  double y(int i) {
    return py[i];
  }

  /** The x of point i's normal (computed on first use: most points are never looked up). */
  double nx(int i) {
    if (!hasNormal[i]) {
      normal(i);
    }
    return pnx[i];
  }

  /** The y of point i's normal. */
  double ny(int i) {
    if (!hasNormal[i]) {
      normal(i);
    }
    return pny[i];
  }

  /** Buckets the points added since {@link #clear()}; call before {@link #nearest}. */
  void build() {
    if (n == 0) {
      gw = 0;
      gh = 0;
      return;
    }
    double maxX = Double.NEGATIVE_INFINITY;
    double maxY = Double.NEGATIVE_INFINITY;
    minX = Double.POSITIVE_INFINITY;
    minY = Double.POSITIVE_INFINITY;
    for (int i = 0; i < n; i++) {
      minX = Math.min(minX, px[i]);
      minY = Math.min(minY, py[i]);
      maxX = Math.max(maxX, px[i]);
      maxY = Math.max(maxY, py[i]);
    }
    cell = CELL;
    while (((maxX - minX) / cell + 1) * ((maxY - minY) / cell + 1) > MAX_CELLS) {
      cell *= 2;
    }
    gw = (int) ((maxX - minX) / cell) + 1;
    gh = (int) ((maxY - minY) / cell) + 1;
    int cells = gw * gh;
    if (start.length < cells + 1) {
      start = new int[cells + 1];
    } else {
      Arrays.fill(start, 0, cells + 1, 0);
    }
    if (items.length < n) {
      items = new int[Math.max(n, items.length * 2)];
    }
    for (int i = 0; i < n; i++) {
      start[cellOf(px[i], py[i]) + 1]++;
    }
    for (int c = 0; c < cells; c++) {
      start[c + 1] += start[c];
    }
    // fill using start[c] as a cursor, then shift back
    for (int i = 0; i < n; i++) {
      items[start[cellOf(px[i], py[i])]++] = i;
    }
    for (int c = cells; c > 0; c--) {
      start[c] = start[c - 1];
    }
    start[0] = 0;
    if (hasNormal.length < n) {
      hasNormal = new boolean[px.length];
    } else {
      Arrays.fill(hasNormal, 0, n, false);
    }
  }

  /**
   * A lone point (far along a wall, where readings are sparse): the normal of the line to its
   * nearest neighbour within {@link #PAIR_RADIUS_MM}, which lies on the same wall; NaN for both if
   * it has none (then it is not matched).
   */
  private void pairNormal(int i) {
    int j = nearestOther(i, PAIR_RADIUS_MM);
    if (j < 0) {
      return;
    }
    double dx = px[j] - px[i];
    double dy = py[j] - py[i];
    double len = Math.hypot(dx, dy);
    pnx[i] = -dy / len;
    pny[i] = dx / len;
  }

  private int nearestOther(int i, double maxDist) {
    double x = px[i];
    double y = py[i];
    int cx = (int) ((x - minX) / cell);
    int cy = (int) ((y - minY) / cell);
    int r = (int) Math.ceil(maxDist / cell);
    double best = maxDist * maxDist;
    int found = -1;
    for (int gy = Math.max(0, cy - r); gy <= Math.min(gh - 1, cy + r); gy++) {
      for (int gx = Math.max(0, cx - r); gx <= Math.min(gw - 1, cx + r); gx++) {
        int c = gy * gw + gx;
        for (int q = start[c]; q < start[c + 1]; q++) {
          int j = items[q];
          double dx = px[j] - x;
          double dy = py[j] - y;
          double d = dx * dx + dy * dy;
          if (j != i && d < best) {
            best = d;
            found = j;
          }
        }
      }
    }
    return found;
  }

  /** A lone point's surface is the line to its nearest neighbour within this, mm. */
  static final double PAIR_RADIUS_MM = 500;

  /** The normal of point i from its neighbours (NaN where they do not lie on a line). */
  private void normal(int i) {
    hasNormal[i] = true;
    double x = px[i];
    double y = py[i];
    int cx = (int) ((x - minX) / cell);
    int cy = (int) ((y - minY) / cell);
    double r2 = NORMAL_RADIUS_MM * NORMAL_RADIUS_MM;
    double sx = 0;
    double sy = 0;
    double sxx = 0;
    double sxy = 0;
    double syy = 0;
    int k = 0;
    for (int gy = Math.max(0, cy - 1); gy <= Math.min(gh - 1, cy + 1); gy++) {
      for (int gx = Math.max(0, cx - 1); gx <= Math.min(gw - 1, cx + 1); gx++) {
        int c = gy * gw + gx;
        for (int q = start[c]; q < start[c + 1]; q++) {
          int j = items[q];
          double dx = px[j] - x;
          double dy = py[j] - y;
          if (dx * dx + dy * dy <= r2) {
            sx += dx;
            sy += dy;
            sxx += dx * dx;
            sxy += dx * dy;
            syy += dy * dy;
            k++;
          }
        }
      }
    }
    pnx[i] = Double.NaN;
    pny[i] = Double.NaN;
    if (k < 4) {
      pairNormal(i);
      return;
    }
    pny[i] = 0; // a corner: matched point to point
    double mx = sx / k;
    double my = sy / k;
    double xx = sxx / k - mx * mx;
    double xy = sxy / k - mx * my;
    double yy = syy / k - my * my;
    double tr = xx + yy;
    double det = xx * yy - xy * xy;
    double disc = Math.sqrt(Math.max(0, tr * tr / 4 - det));
    double small = tr / 2 - disc;
    double large = tr / 2 + disc;
    if (large <= 0 || small > 0.04 * large) {
      return;
    }
    double nx;
    double ny;
    if (Math.abs(xy) > 1e-9) {
      nx = small - yy;
      ny = xy;
    } else if (xx < yy) {
      nx = 1;
      ny = 0;
    } else {
      nx = 0;
      ny = 1;
    }
    double len = Math.hypot(nx, ny);
    pnx[i] = nx / len;
    pny[i] = ny / len;
  }

  private int cellOf(double x, double y) {
    int cx = (int) ((x - minX) / cell);
    int cy = (int) ((y - minY) / cell);
    return cy * gw + cx;
  }

  /** The index of the nearest point within {@code maxDist} of (x, y), or -1. */
  int nearest(double x, double y, double maxDist) {
    if (gw == 0) {
      return -1;
    }
    int cx = (int) Math.floor((x - minX) / cell);
    int cy = (int) Math.floor((y - minY) / cell);
    int r = (int) Math.ceil(maxDist / cell);
    int x0 = Math.max(0, cx - r);
    int x1 = Math.min(gw - 1, cx + r);
    int y0 = Math.max(0, cy - r);
    int y1 = Math.min(gh - 1, cy + r);
    double best = maxDist * maxDist;
    int found = -1;
    for (int gy = y0; gy <= y1; gy++) {
      int row = gy * gw;
      for (int gx = x0; gx <= x1; gx++) {
        int c = row + gx;
        for (int k = start[c]; k < start[c + 1]; k++) {
          int i = items[k];
          double dx = px[i] - x;
          double dy = py[i] - y;
          double d = dx * dx + dy * dy;
          if (d < best) {
            best = d;
            found = i;
          }
        }
      }
    }
    return found;
  }
}
