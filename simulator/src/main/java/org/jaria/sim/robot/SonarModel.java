package org.jaria.sim.robot;

import java.util.Arrays;
import java.util.random.RandomGenerator;
import org.jaria.sim.SonarOptions;
import org.jaria.sim.world.RayHit;
import org.jaria.sim.world.WorldGeometry;

/**
 * The sonar servers: up to four arrays of eight transducers (transducer i belongs to array i / 8),
 * each array firing one transducer at a time every SONARCYCLE ms in its POLLING order. A firing
 * casts a fan of rays over the transducer's cone and reports the nearest echo (see {@link
 * SonarOptions}). New readings wait in a queue for the next SIP; the last reading of every
 * transducer is kept as ground truth.
 *
 * <p>With {@link SonarOptions#allEachSip()} (MobileSim) every transducer of the enabled arrays is
 * measured every {@value SonarOptions#ALL_EACH_SIP_UPDATE_MILLIS} ms instead, nothing is queued,
 * and each SIP carries the last reading of every transducer measured since the session opened
 * ({@link #measuredThisSession}).
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class SonarModel {

  /** Most readings kept for one SIP; older ones are dropped first. */
  public static final int MAX_PENDING = 32;

  /** Default SONARCYCLE, ms. */
  public static final int DEFAULT_CYCLE_MS = 40;

  private static final int ARRAYS = 4;

  private final RobotModel model;
  private final SonarOptions opts;
  private final RandomGenerator rng;
  private final int n;
  private final double cosSpecular;
  private final RayHit hit = new RayHit();

  private final int[][] sequence = new int[ARRAYS][];
  private final int[] next = new int[ARRAYS];
  private final double[] sinceFire = new double[ARRAYS];
  private int enabledArrays;
  private int cycleMs = DEFAULT_CYCLE_MS;

  private final double[] truth;
  private final int[] reported;
  private final double[] hitX;
  private final double[] hitY;
  private final long[] firedAt;
  private final long[] fireCount;

  /** Which transducers were measured since the session opened (all-each-SIP mode). */
  private final boolean[] measured;

  /** Time since every transducer was last measured (all-each-SIP mode), ms. */
  private double sinceAll;

  private final int[] pendingNumber = new int[MAX_PENDING];
  private final int[] pendingRange = new int[MAX_PENDING];
  private int pendingCount;
  private long droppedReadings;

  /** Sonar for {@code model}'s transducers, all arrays disabled until OPEN. */
  public SonarModel(RobotModel model, SonarOptions opts, RandomGenerator rng) {
    this.model = model;
    this.opts = opts;
    this.rng = rng;
    this.n = model.getNumSonar();
    this.cosSpecular = Math.cos(Math.toRadians(opts.specularDegrees()));
    truth = new double[n];
    reported = new int[n];
    hitX = new double[n];
    hitY = new double[n];
    firedAt = new long[n];
    fireCount = new long[n];
    measured = new boolean[n];
    Arrays.fill(truth, Double.NaN);
    Arrays.fill(reported, opts.maxRangeMm());
    resetSettings();
  }

  /** Default firing order (each array in transducer order), default cycle, all arrays off. */
  public void resetSettings() {
    for (int a = 0; a < ARRAYS; a++) {
      int from = Math.min(n, a * 8);
      int to = Math.min(n, a * 8 + 8);
      sequence[a] = new int[to - from];
      for (int i = from; i < to; i++) {
        sequence[a][i - from] = i;
      }
      next[a] = 0;
      sinceFire[a] = 0;
    }
    cycleMs = DEFAULT_CYCLE_MS;
    enabledArrays = 0;
    pendingCount = 0;
    Arrays.fill(measured, false);
    sinceAll = SonarOptions.ALL_EACH_SIP_UPDATE_MILLIS; // measure at the first tick
  }

  /** Turns every array on (OPEN) or off (CLOSE). */
  public void setAllEnabled(boolean on) {
    enabledArrays = on ? 0xF : 0;
    if (!on) {
      Arrays.fill(measured, false);
    }
  }

  /**
   * SONAR: bit 0 enables or disables; bits 1..3 select array 1..4 (0 = all).
   *
   * @param arg the command argument
   */
  public void sonarCommand(int arg) {
    int array = (arg >> 1) & 0x7;
    boolean on = (arg & 1) != 0;
    int mask = array == 0 ? 0xF : (array <= ARRAYS ? 1 << (array - 1) : 0);
    enabledArrays = on ? enabledArrays | mask : enabledArrays & ~mask;
  }

  /**
   * POLLING: a string of transducer numbers 1..32. Only arrays that appear are re-sequenced; an
   * empty string disables all sonar but keeps the sequences.
   */
  public void polling(byte[] numbers) {
    if (numbers.length == 0) {
      enabledArrays = 0;
      return;
    }
    int[][] fresh = new int[ARRAYS][];
    int[] counts = new int[ARRAYS];
    for (byte b : numbers) {
      int i = (b & 0xFF) - 1;
      if (i >= 0 && i < n && i < 32) {
        counts[i / 8]++;
      }
    }
    for (int a = 0; a < ARRAYS; a++) {
      fresh[a] = new int[counts[a]];
      counts[a] = 0;
    }
    for (byte b : numbers) {
      int i = (b & 0xFF) - 1;
      if (i >= 0 && i < n && i < 32) {
        fresh[i / 8][counts[i / 8]++] = i;
      }
    }
    for (int a = 0; a < ARRAYS; a++) {
      if (fresh[a].length > 0) {
        sequence[a] = fresh[a];
        next[a] = 0;
      }
    }
  }

  /** SONARCYCLE: ms between firings of one array, 2..120. */
  public void setCycle(int ms) {
    cycleMs = Math.max(2, Math.min(120, ms));
  }

  /** Current SONARCYCLE, ms. */
  public int getCycle() {
    return cycleMs;
  }

  /** Bits 0..3: which arrays fire. */
  public int getEnabledArrays() {
    return enabledArrays;
  }

  /**
   * Fires every array whose cycle came due during the last {@code dtMs} ms, from the robot's true
   * pose (x, y mm; thRad).
   */
  public void tick(
      double dtMs, double x, double y, double thRad, WorldGeometry world, int self, long nowNanos) {
    if (enabledArrays == 0 || n == 0) {
      return;
    }
    if (opts.allEachSip()) {
      sinceAll += dtMs;
      if (sinceAll >= SonarOptions.ALL_EACH_SIP_UPDATE_MILLIS) {
        sinceAll = 0;
        for (int i = 0; i < n; i++) {
          if (arrayEnabled(i)) {
            fire(i, x, y, thRad, world, self, nowNanos);
          }
        }
      }
      return;
    }
    for (int a = 0; a < ARRAYS; a++) {
      int[] seq = sequence[a];
      if ((enabledArrays & (1 << a)) == 0 || seq.length == 0) {
        continue;
      }
      sinceFire[a] += dtMs;
      while (sinceFire[a] >= cycleMs) {
        sinceFire[a] -= cycleMs;
        int i = seq[next[a]];
        next[a] = (next[a] + 1) % seq.length;
        fire(i, x, y, thRad, world, self, nowNanos);
      }
    }
  }

  /** Fires transducer {@code i} now and queues its reading. */
  void fire(int i, double x, double y, double thRad, WorldGeometry world, int self, long now) {
    double c = Math.cos(thRad);
    double s = Math.sin(thRad);
    double ox = x + c * model.getSonarX(i) - s * model.getSonarY(i);
    double oy = y + s * model.getSonarX(i) + c * model.getSonarY(i);
    double axis = thRad + Math.toRadians(model.getSonarTh(i));
    double cone = Math.toRadians(opts.coneDegrees());
    int rays = opts.rays();
    double best = Double.POSITIVE_INFINITY;
    for (int k = 0; k < rays; k++) {
      double a = rays == 1 ? axis : axis + ((double) k / (rays - 1) - 0.5) * cone;
      double dx = Math.cos(a);
      double dy = Math.sin(a);
      world.cast(ox, oy, dx, dy, opts.maxRangeMm(), self, hit);
      if (!hit.hit() || (opts.specular() && hit.cosIncidence < cosSpecular)) {
        continue;
      }
      if (hit.distance < best) {
        best = hit.distance;
        hitX[i] = ox + dx * best;
        hitY[i] = oy + dy * best;
      }
    }
    int range;
    if (Double.isInfinite(best)) {
      truth[i] = Double.NaN;
      range = opts.maxRangeMm();
    } else {
      truth[i] = best;
      double sigma = opts.noiseMm() + opts.noiseFraction() * best;
      double r = best + (sigma > 0 ? rng.nextGaussian() * sigma : 0);
      if (r < opts.minRangeMm() && opts.nearReadsMin()) {
        range = opts.minRangeMm();
      } else if (r < opts.minRangeMm() || r > opts.maxRangeMm()) {
        range = opts.maxRangeMm();
      } else {
        range = (int) Math.round(r);
      }
    }
    reported[i] = range;
    firedAt[i] = now;
    fireCount[i]++;
    if (opts.allEachSip()) {
      measured[i] = true;
    } else {
      queue(i, range);
    }
  }

  /** Whether transducer {@code i}'s array is enabled. */
  public boolean arrayEnabled(int i) {
    int a = i / 8;
    return a < ARRAYS && (enabledArrays & (1 << a)) != 0;
  }

  /**
   * Whether transducer {@code i} was measured since the session opened and its array is on (in
   * all-each-SIP mode the SIP carries exactly these readings).
   */
  public boolean measuredThisSession(int i) {
    return measured[i] && arrayEnabled(i);
  }

  /** Whether every transducer is measured at once and every SIP carries them all (MobileSim). */
  public boolean allEachSip() {
    return opts.allEachSip();
  }

  private void queue(int number, int range) {
    if (pendingCount == MAX_PENDING) {
      System.arraycopy(pendingNumber, 1, pendingNumber, 0, MAX_PENDING - 1);
      System.arraycopy(pendingRange, 1, pendingRange, 0, MAX_PENDING - 1);
      pendingCount--;
      droppedReadings++;
    }
    pendingNumber[pendingCount] = number;
    pendingRange[pendingCount] = range;
    pendingCount++;
  }

  /** Readings waiting for the next SIP. */
  public int pendingCount() {
    return pendingCount;
  }

  /** Transducer number (0..31) of pending reading {@code k}. */
  public int pendingNumber(int k) {
    return pendingNumber[k];
  }

  /** Range, mm, of pending reading {@code k}. */
  public int pendingRange(int k) {
    return pendingRange[k];
  }

  /** Empties the queue (after a SIP carried the readings). */
  public void clearPending() {
    pendingCount = 0;
  }

  /** Readings dropped because more came between two SIPs than one SIP can carry. */
  public long droppedReadings() {
    return droppedReadings;
  }

  /** Number of transducers. */
  public int size() {
    return n;
  }

  /** Distance to the nearest echo of the last firing of {@code i} before noise, NaN if none. */
  public double trueRange(int i) {
    return truth[i];
  }

  /** Range reported for the last firing of {@code i}, mm (5000 for no echo). */
  public int reportedRange(int i) {
    return reported[i];
  }

  /** X of the echo point of the last firing of {@code i} (valid when trueRange is a number). */
  public double hitX(int i) {
    return hitX[i];
  }

  /** Y of the echo point of the last firing of {@code i}. */
  public double hitY(int i) {
    return hitY[i];
  }

  /** Simulated time of the last firing of {@code i}, ns (0 = never). */
  public long firedAt(int i) {
    return firedAt[i];
  }

  /** How many times {@code i} has fired. */
  public long fireCount(int i) {
    return fireCount[i];
  }

  /** The options in use. */
  public SonarOptions options() {
    return opts;
  }
}
