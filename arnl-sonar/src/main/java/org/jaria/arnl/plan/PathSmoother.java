package org.jaria.arnl.plan;

import org.jaria.arnl.grid.GridSpec;

/**
 * Turns a chain of grid cells into a smooth polyline: cell centres first, then a few rounds of
 * gradient smoothing that pull each point towards the middle of its neighbours while a weaker force
 * keeps it near where the planner put it (in the middle of the corridor). A move that would bring a
 * point closer to an obstacle than the planner's point was (or than the lethal distance plus a
 * comfort margin, whichever is less) is refused, so smoothing never cuts a corner closer than the
 * plan itself. The ends stay where they are.
 */
public final class PathSmoother {

  /** Smoothing may not bring a point nearer than lethal + this to an obstacle, mm. */
  static final double COMFORT = 200;

  private PathSmoother() {}

  /**
   * The smoothed path through {@code cells} of {@code grid}, starting exactly at (startX, startY)
   * and ending exactly at (goalX, goalY).
   */
  public static PlannedPath smooth(
      int[] cells, CostGrid grid, double startX, double startY, double goalX, double goalY) {
    GridSpec s = grid.spec();
    int n = cells.length;
    double[] ox = new double[n + (n == 1 ? 1 : 0)];
    double[] oy = new double[ox.length];
    for (int i = 0; i < n; i++) {
      ox[i] = s.centerX(cells[i] % s.width());
      oy[i] = s.centerY(cells[i] / s.width());
    }
    int m = ox.length;
    ox[0] = startX;
    oy[0] = startY;
    ox[m - 1] = goalX;
    oy[m - 1] = goalY;
    double[] x = ox.clone();
    double[] y = oy.clone();
    double[] keep = new double[m];
    for (int i = 0; i < m; i++) {
      keep[i] = Math.min(grid.clearanceAt(ox[i], oy[i]), grid.lethal() + COMFORT);
    }
    double alpha = 0.1;
    double beta = 0.4;
    for (int round = 0; round < 60; round++) {
      double moved = 0;
      for (int i = 1; i < m - 1; i++) {
        double nx = x[i] + alpha * (ox[i] - x[i]) + beta * (x[i - 1] + x[i + 1] - 2 * x[i]);
        double ny = y[i] + alpha * (oy[i] - y[i]) + beta * (y[i - 1] + y[i + 1] - 2 * y[i]);
        int k = s.indexOf(nx, ny);
        if (grid.isFree(k) && grid.clearance(k) >= keep[i]) {
          moved += Math.abs(nx - x[i]) + Math.abs(ny - y[i]);
          x[i] = nx;
          y[i] = ny;
        }
      }
      if (moved < 0.01 * m) {
        break;
      }
    }
    return new PlannedPath(x, y);
  }
}
