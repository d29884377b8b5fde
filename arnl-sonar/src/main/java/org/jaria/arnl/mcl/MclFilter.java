package org.jaria.arnl.mcl;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;

/**
 * A Monte Carlo localization particle filter for sonar: a set of weighted pose hypotheses moved by
 * odometry ({@link MotionModel}), weighed against the map ({@link LikelihoodField}, {@link
 * SonarScan}) and resampled with the low-variance method, optionally to a KLD-adaptive size.
 *
 * <p>Particles live in primitive arrays ({@code x[], y[], th[], w[]}); updates allocate nothing per
 * particle. Randomness comes from one seeded generator, so the same inputs give the same particles.
 * Not thread-safe: one thread (or a lock) at a time.
 */
public final class MclFilter {

  /** Particles used at most (arrays are sized for this). */
  private final int capacity;

  private LikelihoodField field;
  private final SplittableRandom rng;
  private final double[] x;
  private final double[] y;
  private final double[] th;
  private final double[] w;
  private final double[] nx;
  private final double[] ny;
  private final double[] nth;
  private final double[] ll;
  private final double[][] cs;
  private boolean csValid;
  private int n;
  // Scratch for injectFromScan, allocated on first use.
  private double[] cx;
  private double[] cy;
  private double[] cth;
  private double[] cll;

  private MotionModel motion = MotionModel.DEFAULTS;
  private double sensorBelief = 0.5;
  private double seeThroughLogPenalty = Math.log(0.3);
  private double resampleThreshold = 0.5;
  private boolean adjustNumSamples;
  private int minSamples = 300;
  private double kldEpsilon = 0.05;
  private final KldBins bins;
  private final PoseClusters clusters;

  /**
   * A filter for up to {@code capacity} particles on {@code field}, with randomness from {@code
   * seed}. It starts with no particles: initialize it with {@link #initGaussian} or {@link
   * #initUniform}.
   */
  public MclFilter(LikelihoodField field, int capacity, long seed) {
    if (capacity < 1) {
      throw new IllegalArgumentException("a filter needs room for at least 1 particle");
    }
    this.field = field;
    this.capacity = capacity;
    this.rng = new SplittableRandom(seed);
    x = new double[capacity];
    y = new double[capacity];
    th = new double[capacity];
    w = new double[capacity];
    nx = new double[capacity];
    ny = new double[capacity];
    nth = new double[capacity];
    ll = new double[capacity];
    cs = new double[2][capacity];
    bins = new KldBins(capacity);
    clusters = new PoseClusters(bins);
  }

  // ------------------------------------------------------------------ settings

  /** The odometry noise model. */
  public void setMotionModel(MotionModel m) {
    motion = m;
  }

  /** The odometry noise model. */
  public MotionModel getMotionModel() {
    return motion;
  }

  /**
   * How much one sonar update counts, 0..1: the log-likelihood of a scan is multiplied by it, since
   * the echoes of one scan are far from independent (default 0.5).
   */
  public void setSensorBelief(double b) {
    if (!(b > 0 && b <= 1)) {
      throw new IllegalArgumentException("sensor belief must be in (0, 1], got " + b);
    }
    sensorBelief = b;
  }

  /**
   * Likelihood factor (0..1] for an echo whose axis passes through a mapped wall before reaching
   * its range — which a real echo cannot do, unless the wall was at a grazing angle and reflected
   * the sound away. 1 switches the check off (default 0.3).
   */
  public void setSeeThroughFactor(double f) {
    if (!(f > 0 && f <= 1)) {
      throw new IllegalArgumentException("see-through factor must be in (0, 1], got " + f);
    }
    seeThroughLogPenalty = f == 1 ? 0 : Math.log(f);
  }

  /** Resample when the effective sample size falls below this fraction of the particles. */
  public void setResampleThreshold(double f) {
    resampleThreshold = ArMath.clamp(f, 0, 1);
  }

  /**
   * Whether resampling adapts the number of particles to the spread of the belief (KLD sampling):
   * many while uncertain, few ({@code minSamples} at least) once converged.
   */
  public void setAdjustNumSamples(boolean on, int minSamples, double epsilon) {
    this.adjustNumSamples = on;
    this.minSamples = Math.max(1, Math.min(capacity, minSamples));
    this.kldEpsilon = epsilon > 0 ? epsilon : 0.05;
  }

  /**
   * Switches to another model of the same map (same grid), e.g. a smoother one while searching
   * globally.
   *
   * @throws IllegalArgumentException if the grid differs
   */
  public void setField(LikelihoodField f) {
    if (!f.spec().equals(field.spec())) {
      throw new IllegalArgumentException("the new map model must use the same grid");
    }
    field = f;
  }

  /** The map model. */
  public LikelihoodField getField() {
    return field;
  }

  /** Particles in use. */
  public int size() {
    return n;
  }

  /** Most particles the filter can hold. */
  public int capacity() {
    return capacity;
  }

  // ------------------------------------------------------------------ initialization

  /**
   * Replaces the particles with {@code count} drawn around {@code mean} (standard deviations in mm
   * and degrees), equally weighted.
   */
  public void initGaussian(ArPose mean, int count, double stdX, double stdY, double stdThDeg) {
    csValid = false;
    n = clampCount(count);
    double m = Math.toRadians(mean.th());
    double sth = Math.toRadians(stdThDeg);
    for (int i = 0; i < n; i++) {
      x[i] = mean.x() + rng.nextGaussian() * stdX;
      y[i] = mean.y() + rng.nextGaussian() * stdY;
      th[i] = wrap(m + rng.nextGaussian() * sth);
      w[i] = 1.0 / n;
    }
  }

  /** Replaces the particles with {@code count} spread uniformly over the map's free space. */
  public void initUniform(int count) {
    csValid = false;
    n = clampCount(count);
    for (int i = 0; i < n; i++) {
      placeRandom(i);
      w[i] = 1.0 / n;
    }
  }

  /**
   * Replaces the particles with {@code count} drawn where {@code scan} fits the map (poses on a
   * grid {@code step} mm apart with {@code headings} headings, weighed with the sensor model),
   * except a share {@code uniformShare} spread uniformly over the free space in case the scan
   * misleads (people, furniture not on the map). Equally weighted. The first step of a global
   * search.
   */
  public void initFromScan(
      SonarScan scan, int count, double uniformShare, double step, int headings) {
    csValid = false;
    n = clampCount(count);
    int fromScan = (int) Math.round(n * (1 - ArMath.clamp(uniformShare, 0, 1)));
    if (scan.size() == 0
        || !ScanSeeder.draw(
            field,
            scan,
            step,
            Math.max(1, headings),
            sensorBelief,
            seeThroughLogPenalty,
            rng,
            x,
            y,
            th,
            fromScan)) {
      fromScan = 0;
    }
    for (int i = fromScan; i < n; i++) {
      placeRandom(i);
    }
    double eq = 1.0 / n;
    for (int i = 0; i < n; i++) {
      w[i] = eq;
    }
  }

  /**
   * Replaces a share {@code fraction} of the particles (the lowest weighted first would need a
   * sort; random ones are as good, since weights are equal right after resampling) by random poses
   * in free space, to recover when the robot is lost.
   */
  public void injectRandom(double fraction) {
    csValid = false;
    int k = (int) Math.round(ArMath.clamp(fraction, 0, 1) * n);
    if (k == 0 || field.freeCellCount() == 0) {
      return;
    }
    double mean = 1.0 / n;
    for (int c = 0; c < k; c++) {
      int i = rng.nextInt(n);
      placeRandom(i);
      w[i] = mean * 0.5;
    }
    normalize();
  }

  /**
   * Replaces a share {@code fraction} of the particles by poses where {@code scan} fits the map:
   * {@code candidates} poses are drawn uniformly over the free space, weighed against the scan, and
   * the replacements are drawn from them in proportion to those weights (sensor-resetting
   * recovery). Far more likely than {@link #injectRandom} to put a particle near a kidnapped
   * robot's real pose, at the cost of weighing the candidates (about one update of that many
   * particles). Falls back to {@link #injectRandom} if the scan has no echoes.
   */
  public void injectFromScan(SonarScan scan, double fraction, int candidates) {
    csValid = false;
    int k = (int) Math.round(ArMath.clamp(fraction, 0, 1) * n);
    if (k == 0 || field.freeCellCount() == 0) {
      return;
    }
    if (scan.size() == 0 || candidates < 1) {
      injectRandom(fraction);
      return;
    }
    if (cx == null || cx.length < candidates) {
      cx = new double[candidates];
      cy = new double[candidates];
      cth = new double[candidates];
      cll = new double[candidates];
    }
    int saveN = n;
    for (int c = 0; c < candidates; c++) {
      placeRandom(c, cx, cy, cth);
    }
    SonarLikelihood.score(field, scan, cx, cy, cth, candidates, seeThroughLogPenalty, cll);
    double max = Double.NEGATIVE_INFINITY;
    for (int c = 0; c < candidates; c++) {
      cll[c] *= sensorBelief;
      max = Math.max(max, cll[c]);
    }
    double total = 0;
    for (int c = 0; c < candidates; c++) {
      cll[c] = Math.exp(cll[c] - max);
      total += cll[c];
    }
    double step = total / k;
    double u = rng.nextDouble() * step;
    double acc = cll[0];
    int c = 0;
    double mean = 1.0 / saveN;
    for (int m = 0; m < k; m++) {
      double pick = u + m * step;
      while (pick > acc && c < candidates - 1) {
        c++;
        acc += cll[c];
      }
      int i = rng.nextInt(saveN);
      x[i] = cx[c];
      y[i] = cy[c];
      th[i] = cth[c];
      w[i] = mean;
    }
    normalize();
  }

  private void placeRandom(int i) {
    placeRandom(i, x, y, th);
  }

  private void placeRandom(int i, double[] xs, double[] ys, double[] ths) {
    Resampling.placeRandom(field, rng, i, xs, ys, ths);
  }

  private int clampCount(int count) {
    if (count < 1) {
      throw new IllegalArgumentException("need at least 1 particle, got " + count);
    }
    return Math.min(count, capacity);
  }

  // ------------------------------------------------------------------ motion

  /**
   * Moves every particle by the odometry motion from {@code from} to {@code to} (odometry poses),
   * with noise.
   */
  public void motionUpdate(ArPose from, ArPose to) {
    csValid = false;
    double dx = to.x() - from.x();
    double dy = to.y() - from.y();
    double trans = Math.hypot(dx, dy);
    double th0 = Math.toRadians(from.th());
    double dth = Math.toRadians(ArMath.subAngle(to.th(), from.th()));
    double rot1 = 0;
    if (trans > 1e-3) {
      rot1 = wrap(Math.atan2(dy, dx) - th0);
      if (Math.abs(rot1) > Math.PI / 2) {
        // Driving backwards: a backward move, not a half turn.
        rot1 = wrap(rot1 - Math.PI);
        trans = -trans;
      }
    }
    double rot2 = wrap(dth - rot1);
    double sd1 = Math.sqrt(motion.rotVariance(rot1, trans));
    double sdt = Math.sqrt(motion.transVariance(trans));
    double sd2 = Math.sqrt(motion.rotVariance(rot2, trans));
    for (int i = 0; i < n; i++) {
      double h = th[i] + rot1 + rng.nextGaussian() * sd1;
      double t = trans + rng.nextGaussian() * sdt;
      x[i] += t * Math.cos(h);
      y[i] += t * Math.sin(h);
      th[i] = wrap(h + rot2 + rng.nextGaussian() * sd2);
    }
  }

  /** Spreads the particles a little without moving them (used while standing still). */
  public void jitter(double stdXy, double stdThDeg) {
    csValid = false;
    double s = Math.toRadians(stdThDeg);
    for (int i = 0; i < n; i++) {
      x[i] += rng.nextGaussian() * stdXy;
      y[i] += rng.nextGaussian() * stdXy;
      th[i] = wrap(th[i] + rng.nextGaussian() * s);
    }
  }

  // ------------------------------------------------------------------ sensing

  /**
   * Weighs every particle by how well the scan's echoes fit the map from its pose.
   *
   * @return the mean, over particles, of the per-echo likelihood (geometric mean over echoes): near
   *     1 when echoes fall on walls for most particles, near the random floor when nothing fits; 1
   *     if the scan has no echoes
   */
  public double sensorUpdate(SonarScan scan) {
    int m = scan.size();
    if (m == 0 || n == 0) {
      return 1;
    }
    SonarLikelihood.score(field, scan, x, y, th, headingCosSin(), n, seeThroughLogPenalty, ll);
    double amax = Double.NEGATIVE_INFINITY;
    for (int i = 0; i < n; i++) {
      amax = Math.max(amax, sensorBelief * ll[i]);
    }
    double sum = 0;
    double meanLik = 0;
    for (int i = 0; i < n; i++) {
      w[i] *= Math.exp(sensorBelief * ll[i] - amax);
      sum += w[i];
      meanLik += Math.exp(ll[i] / m);
    }
    if (!(sum > 0)) {
      for (int i = 0; i < n; i++) {
        w[i] = Math.exp(sensorBelief * ll[i] - amax);
      }
    }
    normalize();
    return meanLik / n;
  }

  /**
   * Share of the scan's echoes that the map explains from {@code pose} (ARNL's localization score):
   * an echo is explained when the nearest mapped surface in its cone (found by tracing the cone's
   * rays through the distance field) lies within {@code matchDistance} of its range. This is
   * stricter than the filter's own arc test, so that a robot carried elsewhere scores low even
   * where some arc happens to touch a wall. −1 if the scan has no echoes.
   */
  public double matchFraction(ArPose pose, SonarScan scan, double matchDistance) {
    return MatchScore.matchFraction(field, pose, scan, matchDistance);
  }

  // ------------------------------------------------------------------ resampling

  /** Effective sample size, 1..n: n when weights are equal, 1 when one particle has them all. */
  public double effectiveSampleSize() {
    double s = 0;
    for (int i = 0; i < n; i++) {
      s += w[i] * w[i];
    }
    return s > 0 ? 1 / s : 0;
  }

  /**
   * Resamples if the effective sample size is below the threshold (or if the sample count should
   * adapt); returns whether it did.
   */
  public boolean resampleIfNeeded() {
    if (n == 0) {
      return false;
    }
    if (effectiveSampleSize() >= resampleThreshold * n && !adjustNumSamples) {
      return false;
    }
    resample();
    return true;
  }

  /**
   * Low-variance (systematic) resampling: one random offset, then evenly spaced picks along the
   * cumulative weights. With KLD adaptation the new count follows the number of occupied pose bins.
   */
  public void resample() {
    if (n == 0) {
      return;
    }
    drawSystematic(adjustNumSamples ? kldTarget() : n);
  }

  /** Low-variance draw of {@code target} particles from the current weighted set. */
  private void drawSystematic(int target) {
    csValid = false;
    double step = 1.0 / target;
    double u = rng.nextDouble() * step;
    double c = w[0];
    int i = 0;
    for (int k = 0; k < target; k++) {
      double pick = u + k * step;
      while (pick > c && i < n - 1) {
        i++;
        c += w[i];
      }
      nx[k] = x[i];
      ny[k] = y[i];
      nth[k] = th[i];
    }
    n = target;
    System.arraycopy(nx, 0, x, 0, n);
    System.arraycopy(ny, 0, y, 0, n);
    System.arraycopy(nth, 0, th, 0, n);
    double eq = 1.0 / n;
    for (int k = 0; k < n; k++) {
      w[k] = eq;
    }
  }

  /** The KLD sample count for the current weights ({@link Resampling#kldTarget}). */
  private int kldTarget() {
    return Resampling.kldTarget(bins, x, y, th, w, n, capacity, minSamples, kldEpsilon);
  }

  private void normalize() {
    double sum = 0;
    for (int i = 0; i < n; i++) {
      sum += w[i];
    }
    if (!(sum > 0)) {
      double eq = 1.0 / n;
      for (int i = 0; i < n; i++) {
        w[i] = eq;
      }
      return;
    }
    double inv = 1 / sum;
    for (int i = 0; i < n; i++) {
      w[i] *= inv;
    }
  }

  // ------------------------------------------------------------------ estimate

  /**
   * The mean of the strongest cluster: particles are binned on a 0.5 m grid, the heaviest 3 × 3
   * block of bins is found, and its particles (refined to those within 1 m of their mean) are
   * averaged, headings on the circle.
   */
  public PoseEstimate estimate() {
    return clusters.estimate(x, y, th, headingCosSin(), w, n);
  }

  /**
   * The mean of the particles around {@code hint} (the previous estimate moved by odometry) if they
   * hold at least half the weight, else {@link #estimate()}. Tracking thus follows its own cluster
   * instead of jumping to a compact group of stragglers elsewhere.
   */
  public PoseEstimate estimateNear(ArPose hint) {
    return clusters.estimateNear(hint, x, y, th, headingCosSin(), w, n);
  }

  /**
   * Cosines and sines of the particles' headings, computed once per change of the headings (the
   * sensor model and the estimate both need them; they were a fifth of a laser update).
   */
  private double[][] headingCosSin() {
    if (csValid) {
      return cs;
    }
    csValid = true;
    double[] c = cs[0];
    double[] s = cs[1];
    for (int i = 0; i < n; i++) {
      c[i] = Math.cos(th[i]);
      s[i] = Math.sin(th[i]);
    }
    return cs;
  }

  /** A saved particle set (see {@link #copyState()}). */
  public static final class Saved {
    private final double[] sx;
    private final double[] sy;
    private final double[] sth;
    private final double[] sw;

    private Saved(double[] sx, double[] sy, double[] sth, double[] sw) {
      this.sx = sx;
      this.sy = sy;
      this.sth = sth;
      this.sw = sw;
    }
  }

  /** A copy of the particle set, to compare hypotheses and keep the best. */
  public Saved copyState() {
    return new Saved(
        Arrays.copyOf(x, n), Arrays.copyOf(y, n), Arrays.copyOf(th, n), Arrays.copyOf(w, n));
  }

  /** Puts back a saved particle set. */
  public void restore(Saved s) {
    csValid = false;
    n = Math.min(capacity, s.sx.length);
    System.arraycopy(s.sx, 0, x, 0, n);
    System.arraycopy(s.sy, 0, y, 0, n);
    System.arraycopy(s.sth, 0, th, 0, n);
    System.arraycopy(s.sw, 0, w, 0, n);
    normalize();
  }

  /** Resamples to exactly {@code count} particles (low-variance), e.g. after convergence. */
  public void resampleTo(int count) {
    if (n > 0) {
      drawSystematic(clampCount(count));
    }
  }

  /** The particles as poses (a copy, for display). */
  public List<ArPose> getSamplePoses() {
    List<ArPose> out = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      out.add(new ArPose(x[i], y[i], Math.toDegrees(th[i])));
    }
    return out;
  }

  /** Copies particle coordinates (x, y mm; heading degrees; weight) into arrays of size ≥ n. */
  public int copySamples(double[] xs, double[] ys, double[] thsDeg, double[] ws) {
    for (int i = 0; i < n; i++) {
      xs[i] = x[i];
      ys[i] = y[i];
      thsDeg[i] = Math.toDegrees(th[i]);
      ws[i] = w[i];
    }
    return n;
  }

  private static double wrap(double a) {
    if (a > Math.PI) {
      a -= 2 * Math.PI;
      if (a > Math.PI) {
        a = Math.IEEEremainder(a, 2 * Math.PI);
      }
    } else if (a <= -Math.PI) {
      a += 2 * Math.PI;
      if (a <= -Math.PI) {
        a = Math.IEEEremainder(a, 2 * Math.PI);
      }
    }
    return a;
  }
}
