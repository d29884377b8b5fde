package org.jaria.arnl.mcl;

import java.util.SplittableRandom;
import org.jaria.arnl.grid.GridSpec;

/**
 * Two jobs of the particle filter that need only the particles' arrays: how many particles the
 * belief needs (KLD sampling) and where a particle goes when it is placed at random. Kept apart
 * from {@link MclFilter} so that the filter reads as its steps (move, weigh, estimate, resample).
 */
final class Resampling {

  private Resampling() {}

  /**
   * The KLD sample count of the weighted particles {@code x, y, th, w} (first {@code n}): the pose
   * bins (200 mm, 200 mm, 10°) hit by a systematic draw of {@code capacity} samples from the
   * current weights give k, and n = (k−1)/(2ε)·(1 − 2/(9(k−1)) + √(2/(9(k−1)))·z)³ with z for 99 %.
   */
  static int kldTarget(
      KldBins bins,
      double[] x,
      double[] y,
      double[] th,
      double[] w,
      int n,
      int capacity,
      int minSamples,
      double kldEpsilon) {
    bins.clear();
    double step = 1.0 / capacity;
    double u = 0.5 * step;
    double c = w[0];
    int i = 0;
    int lastI = -1;
    for (int k = 0; k < capacity; k++) {
      double pick = u + k * step;
      while (pick > c && i < n - 1) {
        i++;
        c += w[i];
      }
      if (i != lastI) {
        bins.add(
            (long) Math.floor(x[i] / 200),
            (long) Math.floor(y[i] / 200),
            (long) Math.floor((th[i] + Math.PI) / Math.toRadians(10)));
        lastI = i;
      }
    }
    int k = bins.size();
    if (k <= 1) {
      return minSamples;
    }
    double z = 2.326;
    double a = 2.0 / (9.0 * (k - 1));
    double b = 1 - a + Math.sqrt(a) * z;
    double need = (k - 1) / (2 * kldEpsilon) * b * b * b;
    return (int) Math.max(minSamples, Math.min(capacity, Math.ceil(need)));
  }

  /** Puts particle {@code i} of {@code xs, ys, ths} at a random pose in the free space. */
  static void placeRandom(
      LikelihoodField field, SplittableRandom rng, int i, double[] xs, double[] ys, double[] ths) {
    GridSpec g = field.spec();
    if (field.freeCellCount() == 0) {
      xs[i] = g.originX() + rng.nextDouble() * g.width() * g.res();
      ys[i] = g.originY() + rng.nextDouble() * g.height() * g.res();
    } else {
      int cell = field.freeCell(rng.nextInt(field.freeCellCount()));
      int col = cell % g.width();
      int row = cell / g.width();
      xs[i] = g.originX() + (col + rng.nextDouble()) * g.res();
      ys[i] = g.originY() + (row + rng.nextDouble()) * g.res();
    }
    ths[i] = (rng.nextDouble() * 2 - 1) * Math.PI;
  }
}
