package org.jaria.arnl;

import java.util.ArrayList;
import java.util.List;
import org.jaria.arnl.mcl.LikelihoodField;
import org.jaria.arnl.mcl.MclFilter;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.map.ArMap;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The computing part of a localization task ({@link ArBaseLocalizationTask}): the map model and the
 * particle filter, and the three things done with them (track, localize at candidate poses, search
 * the whole map). Knows nothing about threads or the robot: the task calls it under its lock, with
 * the odometry poses and readings it captured, so that threaded and synchronous runs compute
 * exactly the same thing.
 */
final class LocalizationEngine {

  private static final Logger log = LoggerFactory.getLogger(LocalizationEngine.class);

  /** Echo spread used while searching globally, mm (smooth, so that nearby particles count). */
  static final double GLOBAL_SIGMA = 400;

  /** What one update found. */
  record Result(PoseEstimate estimate, double score, int echoes, int numSamples) {}

  private final ArMap map;
  private final LocalizationParams p;
  private final double robotRadius;
  private final long seed;
  private LikelihoodField field;
  private LikelihoodField coarse;
  private double fieldRes;
  private double fieldSigma;
  private double fieldZRand;
  private MclFilter filter;
  private ArPose filterEncoder;
  private ArPose lastEstimate;
  private int reseeds;
  private boolean seedPending;

  /** Echoes a scan needs to seed a global search. */
  static final int SEED_MIN_ECHOES = 4;

  /**
   * Share of a global search's first particles spread uniformly rather than where the scan fits.
   */
  static final double SEED_UNIFORM_SHARE = 0.2;

  /** Grid of poses weighed to seed a global search: spacing, mm, and number of headings. */
  static final double SEED_STEP = 200;

  static final int SEED_HEADINGS = 36;

  LocalizationEngine(ArMap map, LocalizationParams p, double robotRadius, long seed) {
    this.map = map;
    this.p = p;
    this.robotRadius = robotRadius;
    this.seed = seed;
    checkField();
  }

  /** Builds (or rebuilds, after the map-model parameters changed) the likelihood field. */
  private void checkField() {
    double res = p.gridResolution.getDouble();
    double sigma = p.sensorSigma.getDouble();
    double zr = p.sensorZRand.getDouble();
    if (field != null && res == fieldRes && sigma == fieldSigma && zr == fieldZRand) {
      return;
    }
    long t0 = System.nanoTime();
    field = LikelihoodField.build(map, res, sigma, zr, robotRadius);
    coarse = field.withSigma(Math.max(sigma, GLOBAL_SIGMA));
    fieldRes = res;
    fieldSigma = sigma;
    fieldZRand = zr;
    log.info("built {} in {} ms", field, (System.nanoTime() - t0) / 1_000_000);
    filter = null;
  }

  LikelihoodField field() {
    return field;
  }

  /** The filter sized for at least {@code count} particles (a new one, reseeded, if too small). */
  private MclFilter filter(int count) {
    checkField();
    if (filter == null || filter.capacity() < count) {
      int cap =
          Math.max(
              count, Math.max(p.numSamples.getInt(), Math.max(p.numSamplesAtInit.getInt(), 1)));
      filter = new MclFilter(field, cap, seed + 7919L * reseeds++);
    }
    filter.setMotionModel(p.motionModel());
    filter.setSensorBelief(p.sensorBelief.getDouble());
    filter.setAdjustNumSamples(
        p.adjustNumSamples.getBool(), p.minNumSamples.getInt(), p.kldEpsilon.getDouble());
    return filter;
  }

  boolean hasParticles() {
    return filter != null && filter.size() > 0;
  }

  /**
   * One tracking (or global search) step: odometry motion since the last step, then the readings
   * (prepared at {@code encoderNow}); recovery particles if {@code lost}.
   */
  Result update(ArPose encoderNow, SonarScan scan, boolean lost) {
    return update(encoderNow, scan, lost, false);
  }

  /**
   * As {@link #update(ArPose, SonarScan, boolean)}; {@code searching} (global localization in
   * progress) keeps scattering a few particles, so that a wrong early guess can still be replaced
   * by the right place when the robot sees more.
   */
  Result update(ArPose encoderNow, SonarScan scan, boolean lost, boolean searching) {
    MclFilter f = filter(Math.max(p.numSamples.getInt(), filterSizeOrZero()));
    // While searching, a smooth model and a fixed count: no particle is near the true pose at
    // first, and shrinking early would lose the right place.
    f.setField(searching ? coarse : field);
    f.setAdjustNumSamples(
        p.adjustNumSamples.getBool() && !searching,
        p.minNumSamples.getInt(),
        p.kldEpsilon.getDouble());
    ArPose hint = null;
    if (filterEncoder != null) {
      f.motionUpdate(filterEncoder, encoderNow);
      if (lastEstimate != null && !searching) {
        hint = ArTransform.between(filterEncoder, lastEstimate).doTransform(encoderNow);
      }
    }
    filterEncoder = encoderNow;
    if (searching && seedPending && scan.size() >= SEED_MIN_ECHOES) {
      // The first scan of a global search places the particles where it fits (and so already
      // counts: it is not weighed in a second time).
      f.initFromScan(scan, f.size(), SEED_UNIFORM_SHARE, SEED_STEP, SEED_HEADINGS);
      seedPending = false;
    } else {
      f.sensorUpdate(scan);
    }
    PoseEstimate est = hint == null ? f.estimate() : f.estimateNear(hint);
    lastEstimate = est.pose();
    double score = f.matchFraction(est.pose(), scan, p.matchDistance.getDouble());
    f.resampleIfNeeded();
    if (searching) {
      // The search was seeded where the first scan fitted; a few uniform particles keep a door
      // open in case that scan misled it.
      f.injectRandom(p.recoveryFraction.getDouble());
    } else if (lost && p.recoverOnFail.getBool()) {
      // Recovery particles go where this scan fits, not just anywhere: a few hundred random
      // particles in a large map almost never land near a lost robot's real pose.
      f.injectFromScan(scan, p.recoveryFraction.getDouble(), p.recoveryCandidates.getInt());
    }
    return new Result(est, score, scan.size(), f.size());
  }

  private int filterSizeOrZero() {
    return filter == null ? 0 : filter.size();
  }

  /**
   * Tries each candidate pose: particles spread around it are weighed against the readings a few
   * times (the robot stands still, so only the spread shrinks); the candidate whose result matches
   * the most echoes wins and its particles are kept.
   *
   * @return the winner's result (score −1 if there were no echoes at all)
   */
  Result localizeAt(
      List<ArPose> candidates,
      ArPose encoderNow,
      SonarScan scan,
      int numSamples,
      double stdX,
      double stdY,
      double stdTh) {
    MclFilter f = filter(numSamples);
    double matchDist = p.matchDistance.getDouble();
    MclFilter.Saved best = null;
    Result bestResult = null;
    for (ArPose c : candidates) {
      f.initGaussian(c, numSamples, stdX, stdY, stdTh);
      if (scan.size() > 0) {
        for (int round = 0; round < 6; round++) {
          f.sensorUpdate(scan);
          f.resample();
          double shrink = 1.0 / (round + 2);
          f.jitter(Math.max(5, 0.2 * stdX * shrink), Math.max(0.3, 0.2 * stdTh * shrink));
        }
        f.sensorUpdate(scan);
      }
      PoseEstimate est = scan.size() > 0 ? f.estimate() : new PoseEstimate(c, stdX, stdY, stdTh, 1);
      double score = f.matchFraction(est.pose(), scan, matchDist);
      if (bestResult == null || score > bestResult.score()) {
        lastEstimate = est.pose();
        bestResult = new Result(est, score, scan.size(), f.size());
        best = f.copyState();
      }
    }
    if (best != null) {
      f.restore(best);
    }
    filterEncoder = encoderNow;
    return bestResult;
  }

  /** Replaces the particles with a Gaussian cloud around {@code pose}, without sensing. */
  void reset(ArPose pose, ArPose encoderNow, int numSamples, double sx, double sy, double sth) {
    filter(numSamples).initGaussian(pose, numSamples, sx, sy, sth);
    filterEncoder = encoderNow;
    lastEstimate = pose;
  }

  /** Spreads particles uniformly over the free space. */
  void startGlobal(ArPose encoderNow, int numSamples) {
    filter(numSamples).initUniform(numSamples);
    filterEncoder = encoderNow;
    lastEstimate = null;
    seedPending = true;
  }

  /** After global convergence: keep only the tracking number of particles. */
  void shrinkTo(int numSamples) {
    if (filter != null && filter.size() > numSamples) {
      filter.resampleTo(numSamples);
    }
  }

  List<ArPose> samples() {
    return filter == null ? new ArrayList<>() : filter.getSamplePoses();
  }

  int numSamples() {
    return filter == null ? 0 : filter.size();
  }
}
