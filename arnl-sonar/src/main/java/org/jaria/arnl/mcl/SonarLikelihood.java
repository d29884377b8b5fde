package org.jaria.arnl.mcl;

import org.jaria.arnl.grid.GridSpec;

/**
 * The sonar sensor model's hot loop: the log-likelihood of a scan for every particle, from
 * primitive arrays and the precomputed likelihood field, allocating nothing.
 */
final class SonarLikelihood {

  private SonarLikelihood() {}

  /**
   * Log-likelihood of {@code scan} for every particle into {@code out}: for each echo, the best
   * likelihood among the points of its arc (the echo came from somewhere in the cone). A laser scan
   * (thin beams, nothing to see through) goes to the faster {@link LaserLikelihood}.
   */
  static void score(
      LikelihoodField field,
      SonarScan scan,
      double[] x,
      double[] y,
      double[] th,
      int n,
      double seeThroughLogPenalty,
      double[] out) {
    score(field, scan, x, y, th, null, n, seeThroughLogPenalty, out);
  }

  /**
   * As {@link #score(LikelihoodField, SonarScan, double[], double[], double[], int, double,
   * double[])}, with the headings' cosines and sines in {@code cs} (or null) for laser scans.
   */
  static void score(
      LikelihoodField field,
      SonarScan scan,
      double[] x,
      double[] y,
      double[] th,
      double[][] cs,
      int n,
      double seeThroughLogPenalty,
      double[] out) {
    if (scan.isBeamScan()) {
      int m = scan.size();
      LaserLikelihood.score(
          field,
          scan,
          x,
          y,
          th,
          cs == null ? null : cs[0],
          cs == null ? null : cs[1],
          n,
          out,
          new double[m],
          new double[m]);
      return;
    }
    GridSpec g = field.spec();
    float[] lik = field.logLikelihoods();
    float outside = field.outsideLogLikelihood();
    double ox = g.originX();
    double oy = g.originY();
    double inv = 1 / g.res();
    int gw = g.width();
    int gh = g.height();
    double[] ax = scan.arcXs();
    double[] ay = scan.arcYs();
    double[] tx = scan.throughXs();
    double[] ty = scan.throughYs();
    byte[] near = field.nearWall();
    double penalty = seeThroughLogPenalty;
    int k = scan.arcSamples();
    int m = scan.size();
    for (int i = 0; i < n; i++) {
      double c = Math.cos(th[i]);
      double s = Math.sin(th[i]);
      double px = x[i] - ox;
      double py = y[i] - oy;
      double total = 0;
      int base = 0;
      for (int e = 0; e < m; e++) {
        float best = outside;
        for (int a = 0; a < k; a++, base++) {
          double lx = ax[base];
          double ly = ay[base];
          double gx = (px + c * lx - s * ly) * inv;
          double gy = (py + s * lx + c * ly) * inv;
          if (gx >= 0 && gy >= 0) {
            int ci = (int) gx;
            int cj = (int) gy;
            if (ci < gw && cj < gh) {
              float v = lik[cj * gw + ci];
              if (v > best) {
                best = v;
              }
            }
          }
        }
        total += best;
        int t0 = scan.throughStart(e);
        int count = scan.throughStart(e + 1) - t0;
        if (penalty < 0 && count > 0) {
          // The points are evenly spaced on a line: step along it instead of transforming each,
          // and check the grid bounds once, at the two ends (the segment between stays inside).
          double gx = (px + c * tx[t0] - s * ty[t0]) * inv;
          double gy = (py + s * tx[t0] + c * ty[t0]) * inv;
          double dx = 0;
          double dy = 0;
          if (count > 1) {
            double sx = tx[t0 + 1] - tx[t0];
            double sy = ty[t0 + 1] - ty[t0];
            dx = (c * sx - s * sy) * inv;
            dy = (s * sx + c * sy) * inv;
          }
          double ex = gx + dx * (count - 1);
          double ey = gy + dy * (count - 1);
          if (gx >= 0 && gy >= 0 && gx < gw && gy < gh && ex >= 0 && ey >= 0 && ex < gw
              && ey < gh) {
            for (int t = 0; t < count; t++) {
              if (near[((int) gy) * gw + (int) gx] != 0) {
                total += penalty;
                break;
              }
              gx += dx;
              gy += dy;
            }
          }
        }
      }
      out[i] = total;
    }
  }
}
