package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A scan match's information is measured along the map's axes; the pose graph measures an edge's
 * error in the matched pose's own frame, so the information must be turned with the pose.
 */
class GraphInfoTest {

  /** A corridor along the map's y axis: walls pin x (across) well, y (along) not at all. */
  private static final double[] NORTH_SOUTH_CORRIDOR = {0.1, 0, 0, 0, 0, 1000};

  @Test
  void aRobotDrivingUpACorridorIsPinnedSidewaysNotAhead() {
    // heading 90 degrees: the robot's ahead is the map's y, its left the map's -x
    double[] g = MapBuilder.toGraphInfo(NORTH_SOUTH_CORRIDOR, 90);
    assertEquals(1, g[0], 1e-6, "ahead (along the corridor): only the floor");
    assertEquals(0.1 * 1e6 + 1, g[3], 1e-6, "sideways (across the corridor): the walls");
    assertEquals(0, g[1], 1e-6);
    assertEquals(1001, g[5], 1e-9);
  }

  @Test
  void facingAlongTheMapsAxisChangesNothingButUnits() {
    double[] g = MapBuilder.toGraphInfo(NORTH_SOUTH_CORRIDOR, 0);
    assertEquals(0.1 * 1e6 + 1, g[0], 1e-6);
    assertEquals(1, g[3], 1e-6);
  }

  @Test
  void turningKeepsTheInformationsSizeAndTurnsItsCouplingToHeading() {
    double[] mm = {0.04, 0.01, 2, 0.02, -1, 500};
    for (double th = -180; th <= 180; th += 30) {
      double[] g = MapBuilder.toGraphInfo(mm, th);
      // trace and determinant of the position block do not depend on the frame
      assertEquals((0.04 + 0.02) * 1e6 + 2, g[0] + g[3], 1e-3, "trace at " + th);
      double det = (0.04 * 0.02 - 0.01 * 0.01) * 1e12;
      double gdet = (g[0] - 1) * (g[3] - 1) - g[1] * g[1];
      assertEquals(det, gdet, 1e-3 * det, "determinant at " + th);
      double coupling = Math.hypot(g[2], g[4]);
      assertEquals(Math.hypot(2, -1) * 1e3, coupling, 1e-6, "coupling at " + th);
    }
    double[] back = MapBuilder.toGraphInfo(mm, 180);
    assertTrue(back[2] < 0 && back[4] > 0, "facing back, the coupling changes sign");
  }
}
