package org.jaria.params;

import java.util.HashSet;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * Whether a parameter set can describe a robot, checked when each layer is built: plausible values
 * and sonar units that agree with SonarNum. A failure is a {@link ParamFormatException} naming the
 * file and line to fix.
 */
final class ParamChecks {

  private ParamChecks() {}

  /**
   * Values that cannot describe a robot are errors naming the key and the line that set it: a
   * conversion factor or divisor of zero or less (every distance, speed or range would be zero or
   * infinite) and a negative size.
   */
  static void plausible(ArRobotParams p) throws ParamFormatException {
    positive(p, "AngleConvFactor", p.getAngleConvFactor());
    positive(p, "DistConvFactor", p.getDistConvFactor());
    positive(p, "VelConvFactor", p.getVelConvFactor());
    positive(p, "RangeConvFactor", p.getRangeConvFactor());
    positive(p, "Vel2Divisor", p.getVel2Divisor());
    notNegative(p, "RobotRadius", p.getRobotRadius());
    notNegative(p, "RobotDiagonal", p.getRobotDiagonal());
    notNegative(p, "RobotWidth", p.getRobotWidth());
    notNegative(p, "RobotLength", p.getRobotLength());
    notNegative(p, "RobotLengthFront", p.getRobotLengthFront());
    notNegative(p, "RobotLengthRear", p.getRobotLengthRear());
  }

  private static void positive(ArRobotParams p, String key, double value)
      throws ParamFormatException {
    if (!(value > 0)) {
      ParamFile.Entry e = p.raw.get(key.toLowerCase(Locale.ROOT));
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          key
              + " must be greater than 0, not "
              + e.value()
              + " (it multiplies or divides what the"
              + " robot reports; copy the value from the robot's bundled parameter file)");
    }
  }

  private static void notNegative(ArRobotParams p, String key, double value)
      throws ParamFormatException {
    if (value < 0) {
      ParamFile.Entry e = p.raw.get(key.toLowerCase(Locale.ROOT));
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          key + " is a size in mm and cannot be negative, not " + e.value());
    }
  }

  /**
   * SonarNum and the SonarUnit lines must agree: a unit this file lists beyond SonarNum, or a unit
   * 0..SonarNum-1 that no layer lists, is an error at the line concerned.
   */
  static void sonarCount(
      ArRobotParams p, ParamFile.Entry sonarNum, Map<Integer, ParamFile.Entry> unitLines)
      throws ParamFormatException {
    for (Map.Entry<Integer, ParamFile.Entry> u : unitLines.entrySet()) {
      if (u.getKey() >= p.getNumSonar()) {
        ParamFile.Entry e = u.getValue();
        throw new ParamFormatException(
            e.sourceName(),
            e.line(),
            "SonarUnit "
                + u.getKey()
                + " is listed but SonarNum is "
                + p.getNumSonar()
                + " (units are numbered 0..SonarNum-1): raise SonarNum ("
                + sonarNum.where()
                + ") or remove the unit");
      }
    }
    if (p.getNumSonar() > 0 && !p.sonarUnits.keySet().containsAll(rangeSet(p.getNumSonar()))) {
      Set<Integer> missing = new TreeSet<>(rangeSet(p.getNumSonar()));
      missing.removeAll(p.sonarUnits.keySet());
      throw new ParamFormatException(
          sonarNum.sourceName(),
          sonarNum.line(),
          "SonarNum is "
              + p.getNumSonar()
              + " but no SonarUnit line describes sonar "
              + missing
              + ": add them or lower SonarNum");
    }
  }

  private static Set<Integer> rangeSet(int n) {
    Set<Integer> s = new HashSet<>();
    for (int i = 0; i < n; i++) {
      s.add(i);
    }
    return s;
  }
}
