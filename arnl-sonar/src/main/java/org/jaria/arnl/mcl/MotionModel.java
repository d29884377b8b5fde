package org.jaria.arnl.mcl;

/**
 * How much a Pioneer's odometry can be trusted, in the rotate–translate–rotate form: a motion
 * measured by odometry is split into a first turn, a straight move and a second turn, and each is
 * disturbed by Gaussian noise whose <em>variance</em> grows in proportion to the motion (as errors
 * of independent wheel ticks add up). So the spread after two 100 mm steps equals the spread after
 * one 200 mm step, and the filter behaves the same whatever the update trigger.
 *
 * @param transStdPerSqrtMetre standard deviation of the distance error after 1 m, as a fraction
 *     (0.05 = 5 cm per metre; after 4 m, 10 cm)
 * @param rotStdPerSqrtRadian standard deviation of the heading error after turning 1 radian,
 *     radians
 * @param rotStdPerSqrtMetre standard deviation of the heading error after driving 1 m straight,
 *     radians (unequal wheels)
 * @param minTransStd noise added to every update, mm (keeps duplicated particles apart)
 * @param minRotStd noise added to every update, radians
 */
public record MotionModel(
    double transStdPerSqrtMetre,
    double rotStdPerSqrtRadian,
    double rotStdPerSqrtMetre,
    double minTransStd,
    double minRotStd) {

  /** Defaults for a Pioneer on an indoor floor, about twice its real errors. */
  public static final MotionModel DEFAULTS = new MotionModel(0.05, 0.05, 0.03, 5, 0.005);

  /** Checks the values. */
  public MotionModel {
    if (!(transStdPerSqrtMetre >= 0)
        || !(rotStdPerSqrtRadian >= 0)
        || !(rotStdPerSqrtMetre >= 0)
        || !(minTransStd >= 0)
        || !(minRotStd >= 0)) {
      throw new IllegalArgumentException("motion noise values must be zero or more");
    }
  }

  /** Variance of the distance moved for a straight move of {@code transMm}, mm². */
  public double transVariance(double transMm) {
    return transStdPerSqrtMetre * transStdPerSqrtMetre * 1000 * Math.abs(transMm)
        + minTransStd * minTransStd;
  }

  /**
   * Variance of one of the two turns, rad²: its own share for turning {@code rotRad}, plus half of
   * the heading drift of driving {@code transMm}.
   */
  public double rotVariance(double rotRad, double transMm) {
    return rotStdPerSqrtRadian * rotStdPerSqrtRadian * Math.abs(rotRad)
        + rotStdPerSqrtMetre * rotStdPerSqrtMetre * Math.abs(transMm) / 1000 / 2
        + minRotStd * minRotStd;
  }
}
