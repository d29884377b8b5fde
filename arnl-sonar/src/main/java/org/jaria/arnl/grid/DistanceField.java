package org.jaria.arnl.grid;

import java.util.Arrays;

/**
 * Exact Euclidean distance transform: for every cell, the distance (mm, centre to centre) to the
 * nearest obstacle cell. Computed in linear time with Felzenszwalb and Huttenlocher's
 * lower-envelope-of-parabolas method, one pass over rows and one over columns.
 */
public final class DistanceField {

  private static final float INF = 1e20f;

  private DistanceField() {}

  /**
   * Distances from every cell of {@code g} to the nearest true cell of {@code occ}, mm, capped at
   * {@code cap}. A grid without obstacles is {@code cap} everywhere.
   */
  public static float[] compute(boolean[] occ, GridSpec g, double cap) {
    int w = g.width();
    int h = g.height();
    float[] d2 = new float[w * h];
    for (int k = 0; k < d2.length; k++) {
      d2[k] = occ[k] ? 0 : INF;
    }
    int n = Math.max(w, h);
    double[] f = new double[n];
    double[] out = new double[n];
    int[] v = new int[n];
    double[] z = new double[n + 1];
    for (int j = 0; j < h; j++) {
      for (int i = 0; i < w; i++) {
        f[i] = d2[j * w + i];
      }
      transform1d(f, w, out, v, z);
      for (int i = 0; i < w; i++) {
        d2[j * w + i] = (float) out[i];
      }
    }
    for (int i = 0; i < w; i++) {
      for (int j = 0; j < h; j++) {
        f[j] = d2[j * w + i];
      }
      transform1d(f, h, out, v, z);
      for (int j = 0; j < h; j++) {
        d2[j * w + i] = (float) out[j];
      }
    }
    float res = (float) g.res();
    float c = (float) cap;
    for (int k = 0; k < d2.length; k++) {
      float d = d2[k] >= INF / 2 ? c : (float) Math.sqrt(d2[k]) * res;
      d2[k] = Math.min(d, c);
    }
    return d2;
  }

  /** Squared distance transform of one line (Felzenszwalb & Huttenlocher 2012). */
  private static void transform1d(double[] f, int n, double[] d, int[] v, double[] z) {
    int k = 0;
    int first = -1;
    for (int q = 0; q < n; q++) {
      if (f[q] < INF) {
        first = q;
        break;
      }
    }
    if (first < 0) {
      Arrays.fill(d, 0, n, INF);
      return;
    }
    v[0] = first;
    z[0] = Double.NEGATIVE_INFINITY;
    z[1] = Double.POSITIVE_INFINITY;
    for (int q = first + 1; q < n; q++) {
      if (f[q] >= INF) {
        continue;
      }
      double s;
      while (true) {
        int p = v[k];
        s = ((f[q] + (double) q * q) - (f[p] + (double) p * p)) / (2.0 * q - 2.0 * p);
        if (s <= z[k] && k > 0) {
          k--;
        } else {
          break;
        }
      }
      k++;
      v[k] = q;
      z[k] = s;
      z[k + 1] = Double.POSITIVE_INFINITY;
    }
    k = 0;
    for (int q = 0; q < n; q++) {
      while (z[k + 1] < q) {
        k++;
      }
      double dq = q - v[k];
      d[q] = dq * dq + f[v[k]];
    }
  }
}
