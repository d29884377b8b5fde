package org.jaria.arnl.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

class NavigationMapTest {

  /** A wall at y = 1000 with a one-metre door (x from -500 to 500), and a far wall at y = 3000. */
  private static NavigationMap doorway() {
    ArMap m = new ArMap();
    m.setLines(
        List.of(
            new ArLineSegment(-4000, 1000, -500, 1000),
            new ArLineSegment(500, 1000, 4000, 1000),
            new ArLineSegment(-4000, 3000, 4000, 3000)));
    m.addMapObject(ArMapObject.forbiddenLine(-4000, -1000, 4000, -1000));
    return NavigationMap.build(m, 100, 250, 1000, 4);
  }

  @Test
  void expectedSonarRangeIsTheNearestMappedWallInTheCone() {
    NavigationMap nav = doorway();
    double north = Math.PI / 2;
    // A 30 degree cone through the door reaches the far wall ...
    assertEquals(2000, nav.expectedSonarRange(0, 1000, north, Math.toRadians(15), 4000), 80);
    assertEquals(3000, nav.expectedSonarRange(0, 0, north, Math.toRadians(10), 4000), 80);
    // ... a wider one meets the door frame: an echo from there is the wall, not an obstacle.
    double frame = nav.expectedSonarRange(0, 0, north, Math.toRadians(30), 4000);
    assertTrue(frame > 1000 && frame < 1250, "door frame at " + frame);
    // Forbidden lines are not walls: a sonar does not hear them.
    assertEquals(
        Double.MAX_VALUE, nav.expectedSonarRange(0, 0, -north, Math.toRadians(15), 1800), 0);
    assertTrue(nav.clearanceAt(0, -900) < 150, "but the planner keeps away from them");
  }
}
