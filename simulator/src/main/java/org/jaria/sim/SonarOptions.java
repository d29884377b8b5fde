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
 * {@code maxRangeMm} (5000); with {@code nearReadsMin} (MobileSim) an echo closer than {@code
 * minRangeMm} reads {@code minRangeMm} instead.
 *
 * <p>When the transducers fire: on a real Pioneer ({@code allEachSip} off) each sonar array fires
 * one transducer every SONARCYCLE ms, so a SIP carries the few readings taken since the last one.
 * MobileSim ({@code allEachSip} on) measures every transducer at each update of its world (every
 * 100 ms) and sends all their readings in every SIP.
 *
 * @param coneDegrees full opening angle of the cone, degrees
 * @param rays rays cast per firing (1 = the axis only)
 * @param noiseMm constant part of the noise, mm (standard deviation)
 * @param noiseFraction part of the noise proportional to the range
 * @param minRangeMm echoes nearer than this read as no echo
 * @param maxRangeMm range reported for no echo, and the farthest echo
 * @param specular whether grazing surfaces return no echo
 * @param specularDegrees incidence angle (from the surface normal) beyond which a ray is lost
 * @param nearReadsMin whether an echo nearer than {@code minRangeMm} reads {@code minRangeMm}
 *     (MobileSim) rather than no echo (ARCOS)
 * @param allEachSip whether every transducer is measured every 100 ms and every SIP carries all the
 *     readings (MobileSim) rather than the sonar cycle's (ARCOS)
 */
public record SonarOptions(
    double coneDegrees,
    int rays,
    double noiseMm,
    double noiseFraction,
    int minRangeMm,
    int maxRangeMm,
    boolean specular,
    double specularDegrees,
    boolean nearReadsMin,
    boolean allEachSip) {

  /** ARCOS-like defaults: 30° cone, 7 rays, 10 mm + 0.5 % noise, 120..5000 mm, specular at 65°. */
  public static final SonarOptions DEFAULTS =
      new SonarOptions(30, 7, 10, 0.005, 120, 5000, true, 65, false, false);

  /**
   * MobileSim's sonar: one ray along each transducer's axis, 100..5000 mm (nearer echoes read 100),
   * no specular reflection, about ±0.5 mm of noise (MobileSim's is uniform within ±0.5 mm; this is
   * a Gaussian of the same spread), every transducer measured every 100 ms and all of them in every
   * SIP.
   */
  public static final SonarOptions MOBILESIM =
      new SonarOptions(0, 1, 0.29, 0, 100, 5000, false, 65, true, true);

  /** Time between two measurements of every transducer in {@link #allEachSip} mode, ms. */
  public static final int ALL_EACH_SIP_UPDATE_MILLIS = 100;

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
        coneDegrees,
        rays,
        noiseMm,
        noiseFraction,
        minRangeMm,
        maxRangeMm,
        on,
        specularDegrees,
        nearReadsMin,
        allEachSip);
  }

  /** These options with the given noise. */
  public SonarOptions withNoise(double mm, double fraction) {
    return new SonarOptions(
        coneDegrees,
        rays,
        mm,
        fraction,
        minRangeMm,
        maxRangeMm,
        specular,
        specularDegrees,
        nearReadsMin,
        allEachSip);
  }
}
