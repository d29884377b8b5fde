package org.jaria.arnl.mcl;

import java.util.ArrayDeque;
import java.util.Arrays;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;

/**
 * What the sonar model needs to know about the map, precomputed once: for every cell of a fine
 * grid, the distance to the nearest face of a mapped wall ({@link MapSurfaces}), and the
 * log-likelihood of an echo coming from that cell ({@code log(zRand + (1 − zRand)·exp(−d²/2σ²))}).
 * Also the free space a lost robot may be in, for global localization and recovery. Immutable and
 * shared between threads.
 */
public final class LikelihoodField {

  private final GridSpec spec;
  private final float[] dist;
  private final float[] logLik;
  private final short[] logLik16;
  private final double logLik16Step;
  private final byte[] nearWall;
  private final float outsideLogLik;
  private final int[] freeCells;
  private final double sigma;
  private final double zRand;

  private LikelihoodField(
      GridSpec spec, float[] dist, double sigma, double zRand, int[] freeCells) {
    this.spec = spec;
    this.dist = dist;
    this.sigma = sigma;
    this.zRand = zRand;
    this.logLik = new float[dist.length];
    double inv = 1 / (2 * sigma * sigma);
    for (int k = 0; k < dist.length; k++) {
      double d = dist[k];
      logLik[k] = (float) Math.log(zRand + (1 - zRand) * Math.exp(-d * d * inv));
    }
    this.outsideLogLik = (float) Math.log(zRand);
    // The laser loop reads 16-bit steps of the log-likelihood (log(zRand)/32767 each, 7e-5 for
    // the laser default): half the memory of floats, and an integer sum per particle.
    this.logLik16Step = -outsideLogLik / 32767.0;
    this.logLik16 = new short[dist.length];
    for (int k = 0; k < dist.length; k++) {
      logLik16[k] = (short) Math.max(-32767, Math.round(logLik[k] / logLik16Step));
    }
    // A byte per cell for the see-through test: a quarter of the memory of the distances, so the
    // hot loop stays in cache.
    this.nearWall = new byte[dist.length];
    for (int k = 0; k < dist.length; k++) {
      nearWall[k] = (byte) (dist[k] < SonarScan.THROUGH_NEAR ? 1 : 0);
    }
    this.freeCells = freeCells;
  }

  /**
   * Builds the field for {@code map}.
   *
   * @param res cell size, mm (50 is a good value for sonar)
   * @param sigma standard deviation of an echo's distance from the wall that caused it, mm
   * @param zRand likelihood floor of an echo far from any wall (unmapped obstacles, noise), 0..1
   * @param robotRadius free space is where the robot's centre is at least this far from walls
   */
  public static LikelihoodField build(
      ArMap map, double res, double sigma, double zRand, double robotRadius) {
    if (!(sigma > 0) || !(zRand > 0 && zRand < 1)) {
      throw new IllegalArgumentException(
          "sensor model needs sigma > 0 and 0 < zRand < 1, got " + sigma + ", " + zRand);
    }
    GridSpec g = MapSurfaces.centredSpec(map, res);
    boolean[] solid = new boolean[g.size()];
    float[] d = MapSurfaces.faceDistances(map, g, 5000, solid);
    int[] free = freeSpace(g, d, solid, robotRadius, map.findHomePose().orElse(null));
    return new LikelihoodField(g, d, sigma, zRand, free);
  }

  /**
   * Cells where the robot fits: outside walls and clear of their faces by {@code radius}, and
   * connected to {@code home} if the home is such a cell (so that the insides of closed furniture
   * are not candidates).
   */
  private static int[] freeSpace(
      GridSpec g, float[] d, boolean[] solid, double radius, ArPose home) {
    int n = g.size();
    boolean[] fits = new boolean[n];
    int w = g.width();
    int h = g.height();
    for (int j = 1; j < h - 1; j++) {
      for (int i = 1; i < w - 1; i++) {
        // Inside a thick wall the distance to its face can be large too: not a place to be.
        fits[j * w + i] = !solid[j * w + i] && d[j * w + i] >= radius;
      }
    }
    int start = home == null ? -1 : g.indexOf(home.x(), home.y());
    if (start >= 0 && !fits[start]) {
      start = nearestFitting(g, fits, start);
    }
    boolean[] keep;
    if (start < 0) {
      keep = fits;
    } else {
      keep = new boolean[n];
      ArrayDeque<Integer> queue = new ArrayDeque<>();
      keep[start] = true;
      queue.add(start);
      int[] nb = {1, -1, w, -w};
      while (!queue.isEmpty()) {
        int k = queue.poll();
        for (int o : nb) {
          int m = k + o;
          if (m >= 0 && m < n && fits[m] && !keep[m]) {
            keep[m] = true;
            queue.add(m);
          }
        }
      }
    }
    int count = 0;
    for (boolean b : keep) {
      count += b ? 1 : 0;
    }
    int[] cells = new int[count];
    int c = 0;
    for (int k = 0; k < n; k++) {
      if (keep[k]) {
        cells[c++] = k;
      }
    }
    return cells;
  }

  private static int nearestFitting(GridSpec g, boolean[] fits, int start) {
    int w = g.width();
    int si = start % w;
    int sj = start / w;
    for (int r = 1; r < 20; r++) {
      for (int dj = -r; dj <= r; dj++) {
        for (int di = -r; di <= r; di++) {
          int i = si + di;
          int j = sj + dj;
          if (g.inside(i, j) && fits[j * w + i]) {
            return j * w + i;
          }
        }
      }
    }
    return -1;
  }

  /**
   * The same map model with a different echo spread (sharing the distance grid): a wide sigma gives
   * a smooth likelihood for the first steps of a global search, where no particle is yet close to
   * the true pose.
   */
  public LikelihoodField withSigma(double newSigma) {
    if (!(newSigma > 0)) {
      throw new IllegalArgumentException("sigma must be positive, got " + newSigma);
    }
    return new LikelihoodField(spec, dist, newSigma, zRand, freeCells);
  }

  /** The grid. */
  public GridSpec spec() {
    return spec;
  }

  /** Distance to the nearest wall from the cell holding (x, y), mm; 5000 outside the grid. */
  public double distanceAt(double x, double y) {
    int k = spec.indexOf(x, y);
    return k < 0 ? 5000 : dist[k];
  }

  /** The per-cell distance array (shared, do not modify). */
  float[] distances() {
    return dist;
  }

  /** The per-cell log-likelihood array (shared, do not modify). */
  float[] logLikelihoods() {
    return logLik;
  }

  /** 1 for cells within {@link SonarScan#THROUGH_NEAR} of a wall (shared, do not modify). */
  byte[] nearWall() {
    return nearWall;
  }

  /**
   * The per-cell log-likelihood in steps of {@link #logLikelihood16Step()}, −32767 (log zRand) to 0
   * (shared, do not modify).
   */
  short[] logLikelihoods16() {
    return logLik16;
  }

  /** The log-likelihood of one step of {@link #logLikelihoods16()}. */
  double logLikelihood16Step() {
    return logLik16Step;
  }

  /** Log-likelihood of an echo outside the grid. */
  float outsideLogLikelihood() {
    return outsideLogLik;
  }

  /** The sensor model's sigma, mm. */
  public double getSigma() {
    return sigma;
  }

  /** The sensor model's random-echo floor. */
  public double getZRand() {
    return zRand;
  }

  /** Number of free cells (candidates for a lost robot). */
  public int freeCellCount() {
    return freeCells.length;
  }

  /** Free cell number {@code k} (an index into the grid). */
  int freeCell(int k) {
    return freeCells[k];
  }

  @Override
  public String toString() {
    return "LikelihoodField["
        + spec.width()
        + "x"
        + spec.height()
        + " cells of "
        + spec.res()
        + " mm, "
        + freeCells.length
        + " free, sigma "
        + sigma
        + "]";
  }

  /** A copy of the distances, for tests and display. */
  public float[] copyDistances() {
    return Arrays.copyOf(dist, dist.length);
  }
}
