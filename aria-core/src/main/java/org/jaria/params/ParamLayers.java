package org.jaria.params;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * One parameter file laid over a parameter set, as ARIA layers them: the file's keywords replace
 * the set's (within the file, a keyword counts at its first appearance), its {@code SonarUnit} and
 * {@code IRUnit} lines replace the units with the same numbers, and its name is added to the
 * sources.
 */
final class ParamLayers {

  private ParamLayers() {}

  /** The built-in generic Pioneer values, the bottom layer of every set. */
  static ArRobotParams generic() {
    try {
      ParamFile f = ParamFile.parse(GenericParams.TEXT, GenericParams.SOURCE);
      return layer(null, f);
    } catch (ParamFormatException e) {
      throw new IllegalStateException("JAria's built-in parameter defaults are broken", e);
    }
  }

  /**
   * {@code f} on top of {@code base} (null for the first layer).
   *
   * @throws ParamFormatException if a value in {@code f} has the wrong form for its keyword, or the
   *     result cannot describe a robot (see {@link ParamChecks})
   */
  static ArRobotParams layer(ArRobotParams base, ParamFile f) throws ParamFormatException {
    Map<String, ParamFile.Entry> r =
        base == null ? new LinkedHashMap<>() : new LinkedHashMap<>(base.raw);
    SortedMap<Integer, SonarUnit> sonar =
        base == null ? new TreeMap<>() : new TreeMap<>(base.sonarUnits);
    SortedMap<Integer, IRUnit> ir = base == null ? new TreeMap<>() : new TreeMap<>(base.irUnits);
    Set<String> seen = new HashSet<>();
    Map<Integer, ParamFile.Entry> unitLines = new TreeMap<>();
    for (ParamFile.Entry e : f.entries()) {
      String k = e.keyword().toLowerCase(Locale.ROOT);
      if (k.equals("sonarunit")) {
        SonarUnit u = ParamValues.parseSonarUnit(e);
        sonar.put(u.number(), u);
        unitLines.putIfAbsent(u.number(), e);
      } else if (k.equals("irunit")) {
        IRUnit u = ParamValues.parseIRUnit(e);
        ir.put(u.number(), u);
      }
      if (seen.add(k)) {
        r.put(k, e);
      }
    }
    List<String> src = new ArrayList<>(base == null ? List.of() : base.sources);
    src.add(f.getSourceName());
    ArRobotParams p =
        new ArRobotParams(r, sonar, ir, src, base == null ? List.of() : base.problems);
    ParamChecks.sonarCount(p, r.get("sonarnum"), unitLines);
    return p;
  }
}
