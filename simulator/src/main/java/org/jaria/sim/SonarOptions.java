package org.jaria.sim;

/**
 * How simulated sonar transducers see the world.
 *
 * <p>Each firing casts {@code rays} rays spread evenly over a cone of {@code coneDegrees} around
 * the transducer's axis and reports the nearest echo. With {@code specular} on, a ray that meets a
 * surface more than {@code specularDegrees} away from head-on is reflected away and returns no
 * echo, which is why real sonar misses walls seen at a grazing angle. The reported range gets
 * seeded Gaussian noise with standard deviation {@code noiseMm + noiseFraction × range}. As on
 * ARCOS, no echo, an echo beyond {@code maxRangeMm}, or one closer than {@code minRangeMm} reads
 * {@code maxRangeMm} (5000).
 *
 * @param coneDegrees full opening angle of the cone, degrees
 * @param rays rays cast per firing (1 = the axis only)
 * @param noiseMm constant part of the noise, mm (standard deviation)
 * @param noiseFraction part of the noise proportional to the range
 * @param minRangeMm echoes nearer than this read as no echo
 * @param maxRangeMm range reported for no echo, and the farthest echo
 * @param specular whether grazing surfaces return no echo
 * @param specularDegrees incidence angle (from the surface normal) beyond which a ray is lost
 */
public record SonarOptions(
    double coneDegrees,
    int rays,
    double noiseMm,
    double noiseFraction,
    int minRangeMm,
    int maxRangeMm,
    boolean specular,
    double specularDegrees) {

  /** ARCOS-like defaults: 30° cone, 7 rays, 10 mm + 0.5 % noise, 120..5000 mm, specular at 65°. */
  public static final SonarOptions DEFAULTS =
      new SonarOptions(30, 7, 10, 0.005, 120, 5000, true, 65);

  /** Checks the values. */
  public SonarOptions {
    if (!(coneDegrees >= 0 && coneDegrees < 180)) {
      throw new IllegalArgumentException("sonar cone must be 0..180 degrees, was " + coneDegrees);
    }
    if (rays < 1 || rays > 64) {
      throw new IllegalArgumentException("sonar rays must be 1..64, was " + rays);
    }
    if (!(noiseMm >= 0) || !(noiseFraction >= 0)) {
      throw new IllegalArgumentException("sonar noise cannot be negative");
    }
    if (minRangeMm < 0 || maxRangeMm <= minRangeMm || maxRangeMm > 65535) {
      throw new IllegalArgumentException(
          "sonar ranges must satisfy 0 <= min < max <= 65535, were "
              + minRangeMm
              + ", "
              + maxRangeMm);
    }
    if (!(specularDegrees > 0 && specularDegrees <= 90)) {
      throw new IllegalArgumentException(
          "specular angle must be in (0, 90] degrees, was " + specularDegrees);
    }
  }

  /** These options with the specular model switched on or off. */
  public SonarOptions withSpecular(boolean on) {
    return new SonarOptions(
        coneDegrees, rays, noiseMm, noiseFraction, minRangeMm, maxRangeMm, on, specularDegrees);
  }

  /** These options with the given noise. */
  public SonarOptions withNoise(double mm, double fraction) {
    return new SonarOptions(
        coneDegrees, rays, mm, fraction, minRangeMm, maxRangeMm, specular, specularDegrees);
  }
}
