package org.jaria.arnl.mcl;

import org.jaria.geom.ArPose;

/**
 * Turns a weighted particle set into one pose: the heaviest cluster's mean, or, while tracking, the
 * mean of the cluster around where the robot should be. Reuses one bin table, so it allocates
 * nothing per particle. Not thread-safe.
 */
final class PoseClusters {

  private final KldBins bins;

  PoseClusters(KldBins bins) {
    this.bins = bins;
  }

  /**
   * The mean of the strongest cluster: particles are binned on a 0.5 m grid, the heaviest 3 × 3
   * block of bins is found, and its particles (refined to those within 1 m of their mean) are
   * averaged, headings on the circle.
   */
  PoseEstimate estimate(double[] x, double[] y, double[] th, double[][] cs, double[] w, int n) {
    if (n == 0) {
      return new PoseEstimate(ArPose.ORIGIN, Double.MAX_VALUE, Double.MAX_VALUE, 180, 0);
    }
    double bin = 500;
    bins.clear();
    for (int i = 0; i < n; i++) {
      bins.addWeight((long) Math.floor(x[i] / bin), (long) Math.floor(y[i] / bin), 0, w[i]);
    }
    long bestI = 0;
    long bestJ = 0;
    double bestW = -1;
    for (int s = 0; s < bins.slots(); s++) {
      if (!bins.used(s)) {
        continue;
      }
      long bi = bins.keyX(s);
      long bj = bins.keyY(s);
      double total = 0;
      for (long di = -1; di <= 1; di++) {
        for (long dj = -1; dj <= 1; dj++) {
          total += bins.weightOf(bi + di, bj + dj, 0);
        }
      }
      if (total > bestW) {
        bestW = total;
        bestI = bi;
        bestJ = bj;
      }
    }
    double cx = (bestI + 0.5) * bin;
    double cy = (bestJ + 0.5) * bin;
    double[] m = clusterMean(cx, cy, 1.5 * bin * Math.sqrt(2), x, y, th, cs, w, n);
    m = clusterMean(m[0], m[1], 1000, x, y, th, cs, w, n);
    return new PoseEstimate(
        new ArPose(m[0], m[1], Math.toDegrees(m[2])), m[3], m[4], Math.toDegrees(m[5]), m[6]);
  }

  /**
   * The mean of the particles around {@code hint} (the previous estimate moved by odometry) if they
   * hold at least half the weight, else {@link #estimate(double[], double[], double[], double[][],
   * double[], int)}. Tracking thus follows its own cluster instead of jumping to a compact group of
   * stragglers elsewhere.
   */
  PoseEstimate estimateNear(
      ArPose hint, double[] x, double[] y, double[] th, double[][] cs, double[] w, int n) {
    double[] m = clusterMean(hint.x(), hint.y(), 1000, x, y, th, cs, w, n);
    if (m[6] < 0.5) {
      return estimate(x, y, th, cs, w, n);
    }
    m = clusterMean(m[0], m[1], 1000, x, y, th, cs, w, n);
    return new PoseEstimate(
        new ArPose(m[0], m[1], Math.toDegrees(m[2])), m[3], m[4], Math.toDegrees(m[5]), m[6]);
  }

  /**
   * Mean x, y, heading; std x, y, heading; and total weight of particles within radius. {@code cs}
   * holds the cosines and sines of the headings, computed once per estimate by the caller (they
   * were the estimate's main cost).
   */
  private static double[] clusterMean(
      double cx,
      double cy,
      double radius,
      double[] x,
      double[] y,
      double[] th,
      double[][] cs,
      double[] w,
      int n) {
    double[] cos = cs[0];
    double[] sin = cs[1];
    double r2 = radius * radius;
    double sw = 0;
    double sx = 0;
    double sy = 0;
    double sc = 0;
    double ss = 0;
    for (int i = 0; i < n; i++) {
      double dx = x[i] - cx;
      double dy = y[i] - cy;
      if (dx * dx + dy * dy > r2) {
        continue;
      }
      sw += w[i];
      sx += w[i] * x[i];
      sy += w[i] * y[i];
      sc += w[i] * cos[i];
      ss += w[i] * sin[i];
    }
    if (!(sw > 0)) {
      return new double[] {cx, cy, 0, radius, radius, Math.PI, 0};
    }
    double mx = sx / sw;
    double my = sy / sw;
    double mth = Math.atan2(ss, sc);
    double vx = 0;
    double vy = 0;
    double vth = 0;
    for (int i = 0; i < n; i++) {
      double dx = x[i] - cx;
      double dy = y[i] - cy;
      if (dx * dx + dy * dy > r2) {
        continue;
      }
      double ex = x[i] - mx;
      double ey = y[i] - my;
      double et = wrap(th[i] - mth);
      vx += w[i] * ex * ex;
      vy += w[i] * ey * ey;
      vth += w[i] * et * et;
    }
    return new double[] {
      mx, my, mth, Math.sqrt(vx / sw), Math.sqrt(vy / sw), Math.sqrt(vth / sw), sw
    };
  }

  /** The angle in (−π, π]; a difference of two such angles needs at most one turn added. */
  private static double wrap(double a) {
    if (a > Math.PI) {
      return a - 2 * Math.PI;
    }
    return a <= -Math.PI ? a + 2 * Math.PI : a;
  }
}
