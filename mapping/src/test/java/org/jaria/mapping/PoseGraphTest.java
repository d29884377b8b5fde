package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The optimiser spreads a loop's error and drops a loop edge that contradicts everything else. */
class PoseGraphTest {

  private static final double[] INFO = {1e4, 0, 0, 1e4, 0, 1e4};

  /** A square of four 2 m sides driven with odometry that overestimates every turn by 2 degrees. */
  private static PoseGraph square(boolean closeLoop) {
    PoseGraph g = new PoseGraph();
    double x = 0;
    double y = 0;
    double th = 0;
    g.addNode(0, 0, 0);
    for (int i = 1; i <= 4; i++) {
      x += 2000 * Math.cos(Math.toRadians(th));
      y += 2000 * Math.sin(Math.toRadians(th));
      th += 92;
      g.addNode(x, y, th);
      g.addEdge(i - 1, i, 2000, 0, 90, INFO, false); // what matching measured: a true square
    }
    if (closeLoop) {
      g.addEdge(0, 4, 0, 0, 0, INFO, true);
    }
    return g;
  }

  @Test
  void optimisingMakesTheMeasurementsAgree() {
    PoseGraph g = square(true);
    double before = 0;
    for (int k = 0; k < g.edgeCount(); k++) {
      before += g.chi2(k);
    }
    double after = g.optimize(10);
    assertTrue(before > 100 && after < 1e-6, before + " -> " + after);
    assertEquals(2000, g.xMm(1), 0.1);
    assertEquals(2000, g.yMm(2), 0.1);
    assertEquals(0, g.xMm(4), 0.1);
    assertEquals(0, g.yMm(4), 0.1);
    assertEquals(0, g.xMm(0), 0, "the first pose stays where the log put it");
  }

  @Test
  void aLoopEdgeThatContradictsTheRestIsDropped() {
    PoseGraph g = square(false);
    g.addEdge(0, 4, 0, 0, 0, INFO, true);
    g.addEdge(1, 3, 5000, 3000, 45, INFO, true); // a false recognition
    assertEquals(1, g.optimizeDroppingOutliers(10, LoopCloser.MAX_LOOP_CHI2));
    double after = g.optimize(10);
    assertTrue(after < 1e-6, "after dropping: " + after);
    assertEquals(5, g.edgeCount());
    assertEquals(0, g.xMm(4), 0.1);
  }
}
