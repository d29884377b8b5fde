package org.jaria.tools.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/** The benchmark runs and reports every figure (speed is measured, never asserted). */
class SimBenchmarkTest {

  @Test
  void quickRunReportsEveryRowWithItsSpread() {
    String table = SimBenchmark.run(SimBenchmark.Settings.QUICK);
    assertTrue(table.contains("1 p3dx-sh, 16 sonars, laser off, office map"), table);
    assertTrue(table.contains("1 p3dx-sh, 16 sonars, laser on, office map"), table);
    assertTrue(table.contains("10 p3dx-sh in one hall"), table);
    assertTrue(table.contains("100 p3dx-sh in one hall"), table);
    assertTrue(table.contains("lowest..highest"), table);
    for (String lines : new String[] {"100 ", "1000 ", "10000 "}) {
      assertTrue(table.lines().anyMatch(l -> l.startsWith(lines)), table);
    }
  }

  @Test
  void aFigureIsTheMedianOfItsRunsWithTheirRange() {
    SimBenchmark.Figure f = SimBenchmark.Figure.of(new double[] {3000, 1000, 2000, 2600, 2400});
    assertEquals(2400, f.median(), 1e-9);
    assertEquals(1000, f.min(), 1e-9);
    assertEquals(3000, f.max(), 1e-9);
    assertEquals(50 * 2000 / 2400.0, f.spreadPercent(), 1e-9);
    assertEquals(1500, SimBenchmark.Figure.of(new double[] {1000, 2000}).median(), 1e-9);
  }

  @Test
  void theLaserRowsClientReallyGetsScans() {
    long off = bytesInOneSecond(false);
    long on = bytesInOneSecond(true);
    // 181 readings × 5 bytes × 10 scans a second, plus the packet overhead.
    assertTrue(on - off > 181 * 5 * 9, "laser packets arrive: " + off + " vs " + on);
  }

  private static long bytesInOneSecond(boolean laser) {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.defaults())) {
      ScriptedClient c = new ScriptedClient(w.addRobot(RobotOptions.of("p3dx-sh")), 1, laser);
      w.addStepListener(c::onTick);
      w.advance(Duration.ofSeconds(1));
      return c.bytesRead();
    }
  }
}
