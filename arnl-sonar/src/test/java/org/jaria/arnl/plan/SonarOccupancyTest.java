package org.jaria.arnl.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class SonarOccupancyTest {

  private static final double HALF = Math.toRadians(15);

  @Test
  void repeatedEchoesMakeAnObstacleAndCrossingBeamsClearAPhantom() {
    SonarOccupancy g = new SonarOccupancy(8000, 50);
    g.follow(0, 0);
    for (int k = 0; k < 3; k++) {
      g.addReading(0, 0, 0, 1000, 3000, HALF);
    }
    assertTrue(g.logOddsAt(1000, 0) > 1, "the echo's cell is occupied");
    assertTrue(g.logOddsAt(500, 0) < 0, "the cone before it is free");
    assertEquals(0, g.logOddsAt(-500, 0), "behind the sensor nothing is known");
    // The arc's edge (15 degrees off axis) got little evidence ...
    double edge = g.logOddsAt(1000 * Math.cos(HALF * 0.9), 1000 * Math.sin(HALF * 0.9));
    assertTrue(edge < 0.6, "edge evidence " + edge);
    // ... and a beam passing through that spot to a farther wall clears it.
    double ex = 1000 * Math.cos(HALF * 0.9);
    double ey = 1000 * Math.sin(HALF * 0.9);
    g.addReading(ex, ey - 1000, Math.PI / 2, 2500, 3000, HALF);
    assertTrue(g.logOddsAt(ex, ey) < edge, "a beam seeing through it lowers it");
  }

  @Test
  void echoesTheMapExplainsOnlyClearTheConeBeforeThem() {
    SonarOccupancy g = new SonarOccupancy(8000, 50);
    g.follow(0, 0);
    for (int k = 0; k < 3; k++) {
      g.addReading(0, 0, 0, 1000, 3000, HALF, true);
    }
    assertEquals(0, g.logOddsAt(1000, 0), "a known wall's echo adds no obstacle");
    assertEquals(0, g.logOddsAt(1000 * Math.cos(HALF * 0.8), 1000 * Math.sin(HALF * 0.8)));
    assertTrue(g.logOddsAt(500, 0) < 0, "the cone before it is still free");
  }

  @Test
  void noEchoClearsOnlyWeakly() {
    SonarOccupancy g = new SonarOccupancy(8000, 50);
    g.follow(0, 0);
    g.addReading(0, 0, 0, 1000, 3000, HALF);
    float occupied = g.logOddsAt(1000, 0);
    g.addReading(-500, 0, 0, 5000, 3000, HALF);
    assertTrue(g.logOddsAt(1000, 0) > 0 && g.logOddsAt(1000, 0) < occupied);
  }

  @Test
  void followingTheRobotKeepsWhatWasSeen() {
    SonarOccupancy g = new SonarOccupancy(4000, 50);
    g.follow(0, 0);
    g.addReading(0, 0, 0, 1000, 3000, HALF);
    g.addReading(0, 0, 0, 1000, 3000, HALF);
    float before = g.logOddsAt(1000, 0);
    g.follow(1500, 200);
    assertEquals(before, g.logOddsAt(1000, 0), 1e-6);
    List<double[]> cells = new ArrayList<>();
    g.occupiedNear(1500, 200, 1500, 0.6, (x, y) -> cells.add(new double[] {x, y}));
    assertTrue(cells.stream().anyMatch(c -> Math.abs(c[0] - 1000) < 60 && Math.abs(c[1]) < 60));
    g.follow(50_000, 0);
    assertEquals(0, g.logOddsAt(1000, 0), "far away, the grid has moved on");
  }
}
