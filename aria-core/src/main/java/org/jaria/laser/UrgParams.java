package org.jaria.laser;

import java.util.Map;

/**
 * What a URG says about itself in its PP answer: range limits and how its steps map to angles.
 *
 * @param model the model name (MODL)
 * @param minRange shortest valid distance, mm (DMIN); smaller values are error codes
 * @param maxRange longest distance, mm (DMAX)
 * @param stepsPerTurn steps in a full turn (ARES)
 * @param firstStep first measurable step (AMIN)
 * @param lastStep last measurable step (AMAX)
 * @param frontStep the step straight ahead (AFRT)
 * @param rpm motor speed, turns per minute (SCAN)
 */
public record UrgParams(
    String model,
    int minRange,
    int maxRange,
    int stepsPerTurn,
    int firstStep,
    int lastStep,
    int frontStep,
    int rpm) {

  /** A URG-04LX's answer. */
  public static final UrgParams URG_04LX =
      new UrgParams("URG-04LX(Hokuyo Automatic Co.,Ltd.)", 20, 5600, 1024, 44, 725, 384, 600);

  /**
   * Reads a PP answer's pairs.
   *
   * @throws IllegalArgumentException naming a missing or malformed field
   */
  public static UrgParams of(Map<String, String> pp) {
    return new UrgParams(
        pp.getOrDefault("MODL", "?"),
        field(pp, "DMIN"),
        field(pp, "DMAX"),
        field(pp, "ARES"),
        field(pp, "AMIN"),
        field(pp, "AMAX"),
        field(pp, "AFRT"),
        field(pp, "SCAN"));
  }

  private static int field(Map<String, String> pp, String name) {
    String v = pp.get(name);
    if (v == null) {
      throw new IllegalArgumentException("the URG's parameters lack " + name);
    }
    try {
      return Integer.parseInt(v.strip());
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("the URG's " + name + " is not a number: " + v, e);
    }
  }

  /** The angle of {@code step}, degrees. */
  public double angleOf(double step) {
    return (step - frontStep) * 360.0 / stepsPerTurn;
  }

  /** The step nearest {@code deg}, within the measurable steps. */
  public int stepOf(double deg) {
    int s = frontStep + (int) Math.round(deg * stepsPerTurn / 360.0);
    return Math.max(firstStep, Math.min(lastStep, s));
  }

  /** The PP answer's lines (the emulator's side). */
  public String[] infoLines() {
    return new String[] {
      Scip.infoLine("MODL", model),
      Scip.infoLine("DMIN", String.valueOf(minRange)),
      Scip.infoLine("DMAX", String.valueOf(maxRange)),
      Scip.infoLine("ARES", String.valueOf(stepsPerTurn)),
      Scip.infoLine("AMIN", String.valueOf(firstStep)),
      Scip.infoLine("AMAX", String.valueOf(lastStep)),
      Scip.infoLine("AFRT", String.valueOf(frontStep)),
      Scip.infoLine("SCAN", String.valueOf(rpm))
    };
  }
}
