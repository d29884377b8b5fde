package org.jaria.params;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Our own bundled parameter files must describe each robot exactly as ARIA's real files do: every
 * typed value, every sonar, and every keyword both files contain.
 */
class ParamConformanceTest {

  /** Getters whose value legitimately differs (where the values came from). */
  private static final Set<String> NOT_COMPARED =
      Set.of("getSources", "hashCode", "toString", "getClass");

  @ParameterizedTest
  @ValueSource(strings = {"p3dx-sh", "p3at-sh", "p3dx", "p3at"})
  void bundledFileMatchesTheRealOne(String subtype) throws Exception {
    ParamFile realFile = ParamFile.read(ReferenceParams.path(subtype));
    ArRobotParams real = ArRobotParams.defaults().overlay(realFile);
    ArRobotParams ours = ArRobotParams.forSubtype(subtype);

    int compared = 0;
    for (Method m : ArRobotParams.class.getMethods()) {
      if (m.getParameterCount() != 0
          || Modifier.isStatic(m.getModifiers())
          || m.getReturnType() == void.class
          || NOT_COMPARED.contains(m.getName())) {
        continue;
      }
      assertEquals(m.invoke(real), m.invoke(ours), subtype + ": " + m.getName());
      compared++;
    }
    assertTrue(compared >= 45, "compared only " + compared + " getters");

    assertEquals(real.getNumSonar(), ours.getNumSonar());
    for (int i = 0; i < real.getNumSonar(); i++) {
      assertEquals(real.getSonarUnit(i), ours.getSonarUnit(i), subtype + " sonar " + i);
      assertEquals(real.getSonarX(i), ours.getSonarX(i));
      assertEquals(real.getSonarY(i), ours.getSonarY(i));
      assertEquals(real.getSonarTh(i), ours.getSonarTh(i));
    }
    for (int i = 0; i < real.getNumIR(); i++) {
      assertEquals(real.getIRX(i), ours.getIRX(i));
      assertEquals(real.getIRY(i), ours.getIRY(i));
      assertEquals(real.getIRType(i), ours.getIRType(i));
      assertEquals(real.getIRCycles(i), ours.getIRCycles(i));
    }

    ParamFile ourFile = ArRobotParams.bundledFile(subtype).orElseThrow();
    Set<String> common = new LinkedHashSet<>();
    for (ParamFile.Entry e : realFile.entries()) {
      if (ourFile.getEntry(e.keyword()).isPresent()) {
        common.add(e.keyword().toLowerCase(Locale.ROOT));
      }
    }
    assertTrue(common.size() >= 70, subtype + ": only " + common.size() + " keywords in common");
    List<String> mismatches = new ArrayList<>();
    for (String k : common) {
      String a = real.getRaw(k).orElseThrow();
      String b = ours.getRaw(k).orElseThrow();
      if (!sameValue(a, b)) {
        mismatches.add(k + ": real '" + a + "' ours '" + b + "'");
      }
    }
    assertEquals(List.of(), mismatches, subtype);
  }

  private static boolean sameValue(String a, String b) {
    try {
      return Double.parseDouble(a) == Double.parseDouble(b);
    } catch (NumberFormatException notNumbers) {
      return a.equals(b);
    }
  }
}
