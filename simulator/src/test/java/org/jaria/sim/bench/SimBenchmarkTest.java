package org.jaria.sim.bench;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The benchmark runs and reports every figure (speed is measured, never asserted). */
class SimBenchmarkTest {

  @Test
  void quickRunReportsEveryRow() {
    String table = SimBenchmark.run(SimBenchmark.Settings.QUICK);
    assertTrue(table.contains("1 p3dx-sh, 16 sonars, office map"), table);
    assertTrue(table.contains("10 p3dx-sh in one hall"), table);
    assertTrue(table.contains("100 p3dx-sh in one hall"), table);
    for (String lines : new String[] {"100 ", "1000 ", "10000 "}) {
      assertTrue(table.lines().anyMatch(l -> l.startsWith(lines)), table);
    }
  }
}
