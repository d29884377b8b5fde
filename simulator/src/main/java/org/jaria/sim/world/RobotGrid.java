package org.jaria.sim.world;

import java.util.Arrays;
import java.util.List;

/**
 * A coarse uniform grid over the robots' bounding circles, rebuilt every tick, so that a sonar ray
 * or a collision test looks only at the robots near it instead of every robot in the world. Each
 * circle is inflated by how far a robot can move before the next rebuild, so the grid stays valid
 * while the robots move during the tick.
 *
 * <p>Not thread-safe: used by the world thread.
 */
final class RobotGrid {

  private static final double CELL = 1000;
  private static final int MAX_CELLS_PER_ROBOT = 16;

  private double minX;
  private double minY;
  private double cell = CELL;
  private double invCell = 1 / CELL;
  private int nx;
  private int ny;
  private int[] cellStart = new int[1];
  private int[] cellItems = new int[0];
  private int[] counts = new int[0];
  private int[] stamp = new int[0];
  private int currentStamp;

  /** Rebuilds over {@code robots}, each circle inflated by {@code margin} mm. */
  void rebuild(List<Footprint> robots, double margin) {
    int n = robots.size();
    double x0 = Double.POSITIVE_INFINITY;
    double y0 = Double.POSITIVE_INFINITY;
    double x1 = Double.NEGATIVE_INFINITY;
    double y1 = Double.NEGATIVE_INFINITY;
    for (Footprint f : robots) {
      double r = f.boundingRadius() + margin;
      x0 = Math.min(x0, f.centerX() - r);
      y0 = Math.min(y0, f.centerY() - r);
      x1 = Math.max(x1, f.centerX() + r);
      y1 = Math.max(y1, f.centerY() + r);
    }
    minX = x0;
    minY = y0;
    cell = CELL;
    while (cells(x1 - x0, y1 - y0) > Math.max(64, (long) MAX_CELLS_PER_ROBOT * n)) {
      cell *= 2;
    }
    invCell = 1 / cell;
    nx = Math.max(1, (int) Math.ceil((x1 - x0) / cell));
    ny = Math.max(1, (int) Math.ceil((y1 - y0) / cell));
    int total = nx * ny;
    if (counts.length < total) {
      counts = new int[total];
      cellStart = new int[total + 1];
    } else {
      Arrays.fill(counts, 0, total, 0);
    }
    if (stamp.length < n) {
      stamp = new int[Math.max(n, 2 * stamp.length)];
    }
    for (int pass = 0; pass < 2; pass++) {
      if (pass == 1) {
        int sum = 0;
        for (int c = 0; c < total; c++) {
          cellStart[c] = sum;
          sum += counts[c];
          counts[c] = cellStart[c];
        }
        cellStart[total] = sum;
        if (cellItems.length < sum) {
          cellItems = new int[Math.max(sum, 2 * cellItems.length)];
        }
      }
      for (int i = 0; i < n; i++) {
        Footprint f = robots.get(i);
        double r = f.boundingRadius() + margin;
        int ix0 = cx(f.centerX() - r);
        int ix1 = cx(f.centerX() + r);
        int iy0 = cy(f.centerY() - r);
        int iy1 = cy(f.centerY() + r);
        for (int iy = iy0; iy <= iy1; iy++) {
          for (int ix = ix0; ix <= ix1; ix++) {
            int c = iy * nx + ix;
            if (pass == 0) {
              counts[c]++;
            } else {
              cellItems[counts[c]++] = i;
            }
          }
        }
      }
    }
  }

  private long cells(double w, double h) {
    return (long) Math.ceil(w / cell) * (long) Math.ceil(h / cell);
  }

  private int cx(double x) {
    int i = (int) Math.floor((x - minX) * invCell);
    return i < 0 ? 0 : (i >= nx ? nx - 1 : i);
  }

  private int cy(double y) {
    int i = (int) Math.floor((y - minY) * invCell);
    return i < 0 ? 0 : (i >= ny ? ny - 1 : i);
  }

  private int nextStamp() {
    if (++currentStamp == Integer.MAX_VALUE) {
      Arrays.fill(stamp, 0);
      currentStamp = 1;
    }
    return currentStamp;
  }

  /** Visitor of the robots a query may touch. */
  interface Visitor {
    /** Called once per candidate robot; returns false to stop early. */
    boolean visit(int robot);
  }

  /** Visits every robot registered in a cell overlapping the box (each robot once). */
  void visitBox(double x0, double y0, double x1, double y1, Visitor v) {
    int s = nextStamp();
    int ix0 = cx(x0);
    int ix1 = cx(x1);
    int iy0 = cy(y0);
    int iy1 = cy(y1);
    for (int iy = iy0; iy <= iy1; iy++) {
      for (int ix = ix0; ix <= ix1; ix++) {
        int c = iy * nx + ix;
        for (int k = cellStart[c], end = cellStart[c + 1]; k < end; k++) {
          int r = cellItems[k];
          if (stamp[r] != s) {
            stamp[r] = s;
            if (!v.visit(r)) {
              return;
            }
          }
        }
      }
    }
  }

  /**
   * Walks the cells the ray from (ox, oy) along the unit direction crosses, in order, and visits
   * their robots (each once); stops after the cell where the ray reaches {@code maxRange} or the
   * nearest hit found so far ({@code hit.distance}, which visitors may shorten).
   */
  void visitRay(
      double ox, double oy, double dx, double dy, RayHit hit, double maxRange, Visitor v) {
    int s = nextStamp();
    int ix = cx(ox);
    int iy = cy(oy);
    double gx = minX + nx * cell;
    double gy = minY + ny * cell;
    if (ox < minX || ox > gx || oy < minY || oy > gy) {
      // Origin outside the grid: fall back to the cells of the ray's bounding box.
      double len = Math.min(maxRange, hit.distance);
      double ex = ox + dx * len;
      double ey = oy + dy * len;
      visitBox(Math.min(ox, ex), Math.min(oy, ey), Math.max(ox, ex), Math.max(oy, ey), v);
      return;
    }
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
    while (true) {
      int c = iy * nx + ix;
      for (int k = cellStart[c], end = cellStart[c + 1]; k < end; k++) {
        int r = cellItems[k];
        if (stamp[r] != s) {
          stamp[r] = s;
          v.visit(r);
        }
      }
      double tExit = Math.min(tMaxX, tMaxY);
      if (tExit > Math.min(maxRange, hit.distance)) {
        return;
      }
      if (tMaxX < tMaxY) {
        ix += stepX;
        tMaxX += tDeltaX;
        if (ix < 0 || ix >= nx) {
          return;
        }
      } else {
        iy += stepY;
        tMaxY += tDeltaY;
        if (iy < 0 || iy >= ny) {
          return;
        }
      }
    }
  }
}
