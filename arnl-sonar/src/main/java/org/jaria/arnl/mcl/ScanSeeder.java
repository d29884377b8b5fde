package org.jaria.arnl.mcl;

import java.util.SplittableRandom;
import org.jaria.arnl.grid.GridSpec;

/**
 * Finds where a scan fits the map, for global localization: every pose of a coarse grid over the
 * free space (positions {@code step} mm apart, a number of headings) is weighed against the scan
 * with the filter's own sensor model, and particles are drawn in proportion to those weights.
 *
 * <p>Why: a uniform cloud of even 20000 particles puts fewer than one particle near any given pose
 * of a large map, so whichever place happens to hold a well-placed particle wins, right or not. In
 * a building of look-alike rooms that is a coin toss made before the robot has seen anything that
 * tells the rooms apart. Drawing from the scan's fit instead gives every place that explains the
 * readings a well-placed share of particles from the start, and the filter keeps them all until the
 * robot sees the difference.
 */
final class ScanSeeder {

  /** Poses weighed per call of the sensor model. */
  private static final int BATCH = 4096;

  private ScanSeeder() {}

  /**
   * Draws {@code count} particles into {@code x, y, th} (from index 0) in proportion to how well
   * {@code scan} fits at the poses of the grid.
   *
   * @param step spacing of the grid's positions, mm
   * @param headings number of headings tried at each position
   * @param belief the scan's log-likelihood is multiplied by this (as in the filter's updates)
   * @return false if the field has no free space (nothing drawn)
   */
  static boolean draw(
      LikelihoodField field,
      SonarScan scan,
      double step,
      int headings,
      double belief,
      double seeThroughLogPenalty,
      SplittableRandom rng,
      double[] x,
      double[] y,
      double[] th,
      int count) {
    GridSpec g = field.spec();
    int stride = Math.max(1, (int) Math.round(step / g.res()));
    int w = g.width();
    int cells = 0;
    for (int k = 0; k < field.freeCellCount(); k++) {
      int c = field.freeCell(k);
      if ((c % w) % stride == 0 && (c / w) % stride == 0) {
        cells++;
      }
    }
    if (cells == 0 || count <= 0) {
      return false;
    }
    int[] cell = new int[cells];
    int m = 0;
    for (int k = 0; k < field.freeCellCount(); k++) {
      int c = field.freeCell(k);
      if ((c % w) % stride == 0 && (c / w) % stride == 0) {
        cell[m++] = c;
      }
    }
    int poses = cells * headings;
    float[] ll = new float[poses];
    double[] bx = new double[BATCH];
    double[] by = new double[BATCH];
    double[] bth = new double[BATCH];
    double[] out = new double[BATCH];
    double dth = 2 * Math.PI / headings;
    double half = 0.5 * stride * g.res();
    int done = 0;
    while (done < poses) {
      int b = Math.min(BATCH, poses - done);
      for (int q = 0; q < b; q++) {
        int p = done + q;
        int c = cell[p / headings];
        int col = c % w;
        int row = c / w;
        bx[q] = g.originX() + (col + 0.5) * g.res();
        by[q] = g.originY() + (row + 0.5) * g.res();
        bth[q] = -Math.PI + (p % headings + 0.5) * dth;
      }
      SonarLikelihood.score(field, scan, bx, by, bth, b, seeThroughLogPenalty, out);
      for (int q = 0; q < b; q++) {
        ll[done + q] = (float) (belief * out[q]);
      }
      done += b;
    }
    double max = Double.NEGATIVE_INFINITY;
    for (float v : ll) {
      max = Math.max(max, v);
    }
    double total = 0;
    for (int p = 0; p < poses; p++) {
      total += Math.exp(ll[p] - max);
    }
    // Low-variance draw along the cumulative weights, then a uniform jitter within the pose's cell
    // of the grid, so that particles drawn from the same pose are not copies.
    double stepW = total / count;
    double u = rng.nextDouble() * stepW;
    double c = Math.exp(ll[0] - max);
    int p = 0;
    for (int k = 0; k < count; k++) {
      double pick = u + k * stepW;
      while (pick > c && p < poses - 1) {
        p++;
        c += Math.exp(ll[p] - max);
      }
      int cc = cell[p / headings];
      int col = cc % w;
      int row = cc / w;
      x[k] = g.originX() + (col + 0.5) * g.res() + (rng.nextDouble() * 2 - 1) * half;
      y[k] = g.originY() + (row + 0.5) * g.res() + (rng.nextDouble() * 2 - 1) * half;
      double a = -Math.PI + (p % headings + rng.nextDouble()) * dth;
      th[k] = a > Math.PI ? a - 2 * Math.PI : a;
    }
    return true;
  }
}
