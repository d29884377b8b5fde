package org.jaria.arnl.mcl;

import org.jaria.arnl.grid.GridSpec;

/**
 * The laser sensor model's hot loop (a likelihood field): each beam's end point is moved by the
 * particle's pose and looked up once in the field; the scan's log-likelihood is their sum.
 *
 * <p>Why a loop of its own: a laser scan has ten times the sonar's echoes and neither cones nor
 * see-through points, so the general loop's per-echo bookkeeping cost more than the look-ups. Here
 * the end points are scaled to grid cells once per scan, each particle's pose once per particle,
 * and a beam costs two multiply-adds, a bounds test and one read of a float array.
 */
final class LaserLikelihood {

  private LaserLikelihood() {}

  /**
   * Log-likelihood of {@code scan} (one point per echo, no see-through points) for every particle
   * into {@code out}. {@code cos}/{@code sin} hold the cosines and sines of the headings {@code th}
   * if the caller has them (else null: computed here). {@code cellX}/{@code cellY} are scratch
   * arrays of at least {@code scan.size()}.
   */
  static void score(
      LikelihoodField field,
      SonarScan scan,
      double[] x,
      double[] y,
      double[] th,
      double[] cos,
      double[] sin,
      int n,
      double[] out,
      double[] cellX,
      double[] cellY) {
    GridSpec g = field.spec();
    float[] lik = field.logLikelihoods();
    float outside = field.outsideLogLikelihood();
    double inv = 1 / g.res();
    double ox = g.originX();
    double oy = g.originY();
    int gw = g.width();
    int gh = g.height();
    int m = scan.size();
    double[] ax = scan.arcXs();
    double[] ay = scan.arcYs();
    for (int e = 0; e < m; e++) {
      cellX[e] = ax[e] * inv;
      cellY[e] = ay[e] * inv;
    }
    for (int i = 0; i < n; i++) {
      double c = cos == null ? Math.cos(th[i]) : cos[i];
      double s = sin == null ? Math.sin(th[i]) : sin[i];
      double px = (x[i] - ox) * inv;
      double py = (y[i] - oy) * inv;
      double total = 0;
      for (int e = 0; e < m; e++) {
        double lx = cellX[e];
        double ly = cellY[e];
        // Truncation, not floor: the two differ only in (-1, 0), which lands in the grid's outer
        // column or row, a metre of margin away from any wall. One test for all four bounds.
        int ci = (int) (px + c * lx - s * ly);
        int cj = (int) (py + s * lx + c * ly);
        if ((ci | cj | (gw - 1 - ci) | (gh - 1 - cj)) >= 0) {
          total += lik[cj * gw + ci];
        } else {
          total += outside;
        }
      }
      out[i] = total;
    }
  }
}
