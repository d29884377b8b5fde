package org.jaria.arnl.plan;

import java.util.Arrays;
import org.jaria.arnl.grid.DistanceField;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.arnl.grid.MapRaster;
import org.jaria.map.ArMap;

/**
 * The planner's view of the map: for every cell the clearance (distance to the nearest wall, point,
 * forbidden line or forbidden area, mm) and the cost of driving through it. Cells closer to an
 * obstacle than the robot's {@code lethal} radius cannot be entered; between that and {@code
 * freeSpace} the cost rises quadratically towards obstacles, so that the cheapest path keeps to the
 * middle of corridors and doors; beyond {@code freeSpace} every cell costs 1 per mm. Immutable.
 */
public final class CostGrid {

  private final GridSpec spec;
  private final float[] clearance;
  private final float[] cost;
  private final double lethal;
  private final double freeSpace;
  private final double weight;

  private CostGrid(
      GridSpec spec, float[] clearance, double lethal, double freeSpace, double weight) {
    if (!(lethal >= 0) || !(freeSpace > lethal) || !(weight >= 0)) {
      throw new IllegalArgumentException(
          "cost grid needs 0 <= lethal radius < free-space distance and weight >= 0, got "
              + lethal
              + ", "
              + freeSpace
              + ", "
              + weight);
    }
    this.spec = spec;
    this.clearance = clearance;
    this.lethal = lethal;
    this.freeSpace = freeSpace;
    this.weight = weight;
    this.cost = new float[clearance.length];
    for (int k = 0; k < cost.length; k++) {
      cost[k] = costOf(clearance[k]);
    }
  }

  /**
   * The grid for {@code map}: walls, points, forbidden lines and forbidden areas are obstacles.
   *
   * @param res cell size, mm
   * @param lethal the robot's centre may not come closer to an obstacle than this, mm
   * @param freeSpace clearance beyond which a cell costs no extra, mm
   * @param weight extra cost of a cell right at the lethal distance (1 = twice a free cell)
   */
  public static CostGrid build(
      ArMap map, double res, double lethal, double freeSpace, double weight) {
    GridSpec g = MapRaster.specFor(map, res, Math.max(1000, freeSpace));
    boolean[] occ = MapRaster.walls(map, g);
    MapRaster.addForbidden(occ, g, map);
    return fromOccupancy(g, occ, lethal, freeSpace, weight);
  }

  /** The grid for an occupancy array (true = obstacle) laid out as {@code g}. */
  public static CostGrid fromOccupancy(
      GridSpec g, boolean[] occ, double lethal, double freeSpace, double weight) {
    float[] c = DistanceField.compute(occ, g, freeSpace + 1000);
    return new CostGrid(g, c, lethal, freeSpace, weight);
  }

  private float costOf(double c) {
    if (c < lethal) {
      return Float.POSITIVE_INFINITY;
    }
    if (c >= freeSpace) {
      return 1;
    }
    double t = (freeSpace - c) / (freeSpace - lethal);
    return (float) (1 + weight * t * t);
  }

  /**
   * A copy with extra obstacle points (sensed, unmapped) stamped in: every cell's clearance becomes
   * at most its distance to the nearest such point.
   */
  public CostGrid withObstacles(double[] xs, double[] ys, int count) {
    return withObstacles(xs, ys, count, 0);
  }

  /**
   * As {@link #withObstacles(double[], double[], int)}, counting each point {@code allowance} mm
   * farther away than it is: sensed points are small and the local planner avoids them precisely,
   * so the global plan may pass them closer than walls (a narrow gap beside a box stays open).
   */
  public CostGrid withObstacles(double[] xs, double[] ys, int count, double allowance) {
    float[] c = Arrays.copyOf(clearance, clearance.length);
    int r = (int) Math.ceil(freeSpace / spec.res());
    for (int p = 0; p < count; p++) {
      int ci = spec.cellX(xs[p]);
      int cj = spec.cellY(ys[p]);
      for (int j = cj - r; j <= cj + r; j++) {
        for (int i = ci - r; i <= ci + r; i++) {
          if (!spec.inside(i, j)) {
            continue;
          }
          double d = Math.hypot(spec.centerX(i) - xs[p], spec.centerY(j) - ys[p]) + allowance;
          int k = j * spec.width() + i;
          if (d < c[k]) {
            c[k] = (float) d;
          }
        }
      }
    }
    return new CostGrid(spec, c, lethal, freeSpace, weight);
  }

  /** The grid's geometry. */
  public GridSpec spec() {
    return spec;
  }

  /** Traversal cost per mm of cell k; infinite if the robot may not be there. */
  public float cost(int k) {
    return cost[k];
  }

  /** Clearance of cell k, mm. */
  public float clearance(int k) {
    return clearance[k];
  }

  /** Clearance at (x, y), mm; 0 outside the grid. */
  public double clearanceAt(double x, double y) {
    int k = spec.indexOf(x, y);
    return k < 0 ? 0 : clearance[k];
  }

  /** Whether the robot may stand in cell k. */
  public boolean isFree(int k) {
    return k >= 0 && k < cost.length && cost[k] < Float.POSITIVE_INFINITY;
  }

  /** The lethal radius, mm. */
  public double lethal() {
    return lethal;
  }

  /** The free-space distance, mm. */
  public double freeSpace() {
    return freeSpace;
  }

  /** The nearest free cell to cell {@code k} within {@code maxRadius} mm, or −1. */
  public int nearestFree(int k, double maxRadius) {
    if (isFree(k)) {
      return k;
    }
    int w = spec.width();
    int ci = k % w;
    int cj = k / w;
    int rmax = (int) Math.ceil(maxRadius / spec.res());
    int best = -1;
    double bestD = Double.MAX_VALUE;
    for (int r = 1; r <= rmax && best < 0; r++) {
      for (int j = cj - r; j <= cj + r; j++) {
        for (int i = ci - r; i <= ci + r; i++) {
          if (Math.max(Math.abs(i - ci), Math.abs(j - cj)) != r || !spec.inside(i, j)) {
            continue;
          }
          int m = j * w + i;
          double d = Math.hypot(i - ci, j - cj);
          if (isFree(m) && d < bestD) {
            bestD = d;
            best = m;
          }
        }
      }
    }
    return best;
  }
}
