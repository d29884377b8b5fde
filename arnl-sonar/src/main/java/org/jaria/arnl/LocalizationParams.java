package org.jaria.arnl;

import org.jaria.arnl.mcl.MotionModel;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.config.ArPriority;

/**
 * The parameters of a localization task ({@link ArSonarLocalizationTask}, {@link
 * ArLocalizationTask}), registered in the "Localization" section of an {@link ArConfig} (as in
 * ARNL's {@code arnl.p}). Values may be changed at any time, from a file or one by one; the task
 * reads them at every update. The two sensors share most keys; their defaults differ where a laser
 * beam and a sonar echo differ (spread, how much one scan counts, what a good score is), and each
 * has a few keys of its own ({@code Sonar...}, {@code Laser...}).
 */
public final class LocalizationParams {

  /** The config section these parameters live in. */
  public static final String SECTION = "Localization";

  final ArConfigArg numSamples =
      ArConfigArg.ofInt("NumSamples", 2000, "particles used while tracking", 10, 200000);
  final ArConfigArg numSamplesAtInit =
      ArConfigArg.ofInt(
          "NumSamplesAtInit", 2000, "particles when localizing at a known pose", 10, 200000);
  final ArConfigArg globalNumSamples =
      ArConfigArg.ofInt(
          "GlobalNumSamples", 20000, "particles for global localization", 100, 200000);
  final ArConfigArg triggerDistance;
  final ArConfigArg triggerAngle;
  final ArConfigArg passThreshold;
  final ArConfigArg matchDistance;
  final ArConfigArg failuresToLost =
      ArConfigArg.ofInt(
          "FailuresToLost",
          6,
          "consecutive failed updates after which the robot counts as lost",
          1,
          1000);
  final ArConfigArg minEchoes;
  final ArConfigArg sonarMaxRange =
      ArConfigArg.ofDouble(
          "SonarMaxRange", 4500, "echoes at or beyond this are not used, mm", 200, 10000);
  final ArConfigArg sonarMinRange =
      ArConfigArg.ofDouble("SonarMinRange", 150, "shorter echoes are not used, mm", 0, 2000);
  final ArConfigArg coneHalfAngle =
      ArConfigArg.ofDouble(
          "SonarConeHalfAngle", 15, "half the opening of a sonar cone, degrees", 0, 45);
  final ArConfigArg arcSamples =
      ArConfigArg.ofInt("SonarArcSamples", 7, "points tested across each echo's cone", 1, 31);
  final ArConfigArg sensorSigma;
  final ArConfigArg sensorZRand;
  final ArConfigArg sensorBelief;
  final ArConfigArg laserMaxRange =
      ArConfigArg.ofDouble(
          "LaserMaxRange",
          20000,
          "laser readings at or beyond this (or the laser's own maximum) are not used, mm",
          500,
          80000);
  final ArConfigArg laserBeamStep =
      ArConfigArg.ofInt(
          "LaserBeamStep",
          2,
          "use every n-th beam of a laser scan (neighbouring beams tell nearly the same)",
          1,
          50);
  final ArConfigArg gridResolution =
      ArConfigArg.ofDouble("GridResolution", 50, "cell size of the map model, mm", 10, 500);
  final ArConfigArg errorTransPerSqrtM =
      ArConfigArg.ofDouble(
          "KMmPerMm",
          0.05,
          "odometry distance error: standard deviation after 1 m, as a fraction",
          0,
          1);
  final ArConfigArg errorRotPerSqrtRad =
      ArConfigArg.ofDouble(
          "KRadPerRad",
          0.05,
          "odometry turn error: standard deviation after turning 1 radian, radians",
          0,
          2);
  final ArConfigArg errorRotPerSqrtM =
      ArConfigArg.ofDouble(
          "KRadPerMm",
          0.03,
          "heading drift while driving: standard deviation after 1 m, radians",
          0,
          2);
  final ArConfigArg stdX =
      ArConfigArg.ofDouble("StdX", 250, "x spread when localizing at a pose, mm", 0, 10000);
  final ArConfigArg stdY =
      ArConfigArg.ofDouble("StdY", 250, "y spread when localizing at a pose, mm", 0, 10000);
  final ArConfigArg stdTh =
      ArConfigArg.ofDouble(
          "StdTh", 10, "heading spread when localizing at a pose, degrees", 0, 180);
  final ArConfigArg recoverOnFail =
      ArConfigArg.ofBool(
          "RecoverOnFail",
          true,
          "while the robot is lost, replace some particles at each update by poses where the scan"
              + " fits the map");
  final ArConfigArg recoveryFraction =
      ArConfigArg.ofDouble(
          "RecoveryFraction",
          0.05,
          "share of particles replaced per update while lost (or searching globally)",
          0,
          1);
  final ArConfigArg recoveryCandidates =
      ArConfigArg.ofInt(
          "RecoveryCandidates",
          10000,
          "random poses weighed against the scan to choose the recovery particles of an update while lost",
          0,
          200000);
  final ArConfigArg adjustNumSamples =
      ArConfigArg.ofBool(
          "AdjustNumSamples", false, "adapt the particle count to the spread (KLD sampling)");
  final ArConfigArg minNumSamples =
      ArConfigArg.ofInt("MinNumSamples", 300, "fewest particles when the count adapts", 10, 200000);
  final ArConfigArg kldEpsilon =
      ArConfigArg.ofDouble(
          "KldEpsilon", 0.05, "KLD sampling error bound (smaller: more particles)", 0.001, 1);

  private final ArConfig config;

  private final boolean laser;

  /** The sonar parameters with their default values, in a config of their own. */
  public LocalizationParams() {
    this(new ArConfig());
  }

  /** The sonar parameters with their default values, registered in {@code config}. */
  public LocalizationParams(ArConfig config) {
    this(config, false);
  }

  /** The laser parameters ({@link ArLocalizationTask}) with their defaults, in {@code config}. */
  public static LocalizationParams forLaser(ArConfig config) {
    return new LocalizationParams(config, true);
  }

  private LocalizationParams(ArConfig config, boolean laser) {
    this.config = config;
    this.laser = laser;
    triggerDistance =
        ArConfigArg.ofDouble(
            "TriggerDistance",
            laser ? 100 : 200,
            "mm the robot must move before an update",
            1,
            10000);
    triggerAngle =
        ArConfigArg.ofDouble(
            "TriggerAngle",
            laser ? 3 : 5,
            "degrees the robot must turn before an update",
            0.1,
            180);
    passThreshold =
        ArConfigArg.ofDouble(
            "PassThreshold",
            laser ? 0.6 : 0.5,
            laser
                ? "share of laser beams the map must explain for an update to pass"
                : "share of sonar echoes the map must explain for an update to pass",
            0,
            1);
    matchDistance =
        ArConfigArg.ofDouble(
            "MatchDistance",
            laser ? 150 : 250,
            laser
                ? "a beam is explained if the nearest mapped surface along it is this close to its"
                    + " range, mm"
                : "an echo is explained if the nearest mapped surface in its cone is this close to"
                    + " its range, mm",
            10,
            2000);
    minEchoes =
        ArConfigArg.ofInt(
            "MinEchoes",
            laser ? 20 : 3,
            laser
                ? "an update with fewer beam echoes (open areas) neither passes nor fails"
                : "an update with fewer echoes (open areas) neither passes nor fails",
            0,
            laser ? 4096 : 64);
    sensorSigma =
        ArConfigArg.ofDouble(
            "SensorSigma",
            laser ? 50 : 100,
            laser
                ? "spread of a beam's echo around the wall that caused it, mm"
                : "spread of an echo around the wall that caused it, mm",
            5,
            2000);
    sensorZRand =
        ArConfigArg.ofDouble(
            "SensorZRand",
            laser ? 0.1 : 0.2,
            "likelihood of an echo far from any wall (unmapped obstacles), relative to one on a"
                + " wall",
            0.001,
            0.99);
    sensorBelief =
        ArConfigArg.ofDouble(
            "SensorBelief",
            laser ? 0.05 : 0.4,
            laser
                ? "weight of one laser update (the beams of a scan are not independent)"
                : "weight of one sonar update (echoes are not independent)",
            laser ? 0.001 : 0.01,
            1);
    config.addSection(
        SECTION,
        laser
            ? "Monte Carlo localization with a laser (ArLocalizationTask)"
            : "Monte Carlo localization with sonar (ArSonarLocalizationTask)");
    add(numSamples, ArPriority.IMPORTANT);
    add(numSamplesAtInit, ArPriority.NORMAL);
    add(globalNumSamples, ArPriority.NORMAL);
    add(triggerDistance, ArPriority.IMPORTANT);
    add(triggerAngle, ArPriority.IMPORTANT);
    add(passThreshold, ArPriority.IMPORTANT);
    add(matchDistance, ArPriority.NORMAL);
    add(failuresToLost, ArPriority.NORMAL);
    add(minEchoes, ArPriority.DETAILED);
    if (laser) {
      add(laserMaxRange, ArPriority.IMPORTANT);
      add(laserBeamStep, ArPriority.DETAILED);
    } else {
      add(sonarMaxRange, ArPriority.IMPORTANT);
      add(sonarMinRange, ArPriority.DETAILED);
      add(coneHalfAngle, ArPriority.DETAILED);
      add(arcSamples, ArPriority.EXPERT);
    }
    add(sensorSigma, ArPriority.DETAILED);
    add(sensorZRand, ArPriority.EXPERT);
    add(sensorBelief, ArPriority.EXPERT);
    add(gridResolution, ArPriority.EXPERT);
    add(errorTransPerSqrtM, ArPriority.DETAILED);
    add(errorRotPerSqrtRad, ArPriority.DETAILED);
    add(errorRotPerSqrtM, ArPriority.DETAILED);
    add(stdX, ArPriority.NORMAL);
    add(stdY, ArPriority.NORMAL);
    add(stdTh, ArPriority.NORMAL);
    add(recoverOnFail, ArPriority.NORMAL);
    add(recoveryFraction, ArPriority.EXPERT);
    add(recoveryCandidates, ArPriority.EXPERT);
    add(adjustNumSamples, ArPriority.NORMAL);
    add(minNumSamples, ArPriority.DETAILED);
    add(kldEpsilon, ArPriority.EXPERT);
  }

  private void add(ArConfigArg a, ArPriority p) {
    config.addParam(a, SECTION, p);
  }

  /** Whether these are a laser's parameters. */
  public boolean isLaser() {
    return laser;
  }

  /** The config the parameters are registered in. */
  public ArConfig getConfig() {
    return config;
  }

  /** The odometry noise model these values describe. */
  MotionModel motionModel() {
    return new MotionModel(
        errorTransPerSqrtM.getDouble(),
        errorRotPerSqrtRad.getDouble(),
        errorRotPerSqrtM.getDouble(),
        5,
        0.005);
  }

  /** Particles used while tracking. */
  public int getNumSamples() {
    return numSamples.getInt();
  }

  /** Sets the particles used while tracking. */
  public void setNumSamples(int n) {
    numSamples.setInt(n);
  }

  /** Particles used when localizing at a known pose. */
  public int getNumSamplesAtInit() {
    return numSamplesAtInit.getInt();
  }

  /** Sets the particles used when localizing at a known pose. */
  public void setNumSamplesAtInit(int n) {
    numSamplesAtInit.setInt(n);
  }

  /** Particles used for global localization. */
  public int getGlobalNumSamples() {
    return globalNumSamples.getInt();
  }

  /** Sets the particles used for global localization. */
  public void setGlobalNumSamples(int n) {
    globalNumSamples.setInt(n);
  }

  /** mm to move before an update. */
  public double getTriggerDistance() {
    return triggerDistance.getDouble();
  }

  /** Sets the mm to move before an update. */
  public void setTriggerDistance(double mm) {
    triggerDistance.setDouble(mm);
  }

  /** Degrees to turn before an update. */
  public double getTriggerAngle() {
    return triggerAngle.getDouble();
  }

  /** Sets the degrees to turn before an update. */
  public void setTriggerAngle(double deg) {
    triggerAngle.setDouble(deg);
  }

  /** Share of echoes that must match for an update to pass. */
  public double getPassThreshold() {
    return passThreshold.getDouble();
  }

  /** Sets the share of echoes that must match for an update to pass. */
  public void setPassThreshold(double f) {
    passThreshold.setDouble(f);
  }

  /** Whether the particle count adapts (KLD). */
  public boolean getAdjustNumSamples() {
    return adjustNumSamples.getBool();
  }

  /** Sets whether the particle count adapts (KLD). */
  public void setAdjustNumSamples(boolean on) {
    adjustNumSamples.setBool(on);
  }

  /** The parameter called {@code name} (case-insensitive), for tools that list them. */
  public ArConfigArg get(String name) {
    return config
        .findParam(SECTION, name)
        .orElseThrow(() -> new IllegalArgumentException("no localization parameter " + name));
  }
}
