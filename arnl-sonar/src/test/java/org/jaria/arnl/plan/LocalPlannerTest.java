package org.jaria.arnl.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class LocalPlannerTest {

  private static final LocalPlanner.Params P =
      new LocalPlanner.Params(
          600, 60, 300, 300, 100, 242, 210, 301, 212, 30, 1.8, 0.5, 7, 15, 1, 0.6, 0.3, 0.4, 800,
          50);

  private static PlannedPath straight() {
    double[] xs = new double[51];
    double[] ys = new double[51];
    for (int i = 0; i <= 50; i++) {
      xs[i] = i * 100;
    }
    return new PlannedPath(xs, ys);
  }

  @Test
  void drivesAlongAFreePath() {
    LocalPlanner lp = new LocalPlanner();
    LocalPlanner.Command c =
        lp.plan(
            0,
            0,
            0,
            300,
            0,
            straight(),
            0,
            600,
            (x, y) -> 3000,
            new double[0],
            new double[0],
            0,
            P);
    assertFalse(c.blocked());
    assertTrue(c.vel() >= 300, "speeds up: " + c);
    assertEquals(0, c.rotVel(), 10);
  }

  @Test
  void turnsInPlaceWhenThePathIsBehind() {
    LocalPlanner lp = new LocalPlanner();
    LocalPlanner.Command c =
        lp.plan(
            0,
            0,
            180,
            0,
            0,
            straight(),
            0,
            600,
            (x, y) -> 3000,
            new double[0],
            new double[0],
            0,
            P);
    assertEquals(0, c.vel());
    assertTrue(Math.abs(c.rotVel()) > 30, c.toString());
  }

  @Test
  void turnsTheLongWayRoundWhenACornerWouldSweepIntoSomething() {
    LocalPlanner lp = new LocalPlanner();
    // Facing north, the path runs east: the short way is a right turn, but the front-right corner
    // would sweep through a point 280 mm away at 30 degrees.
    double[] ox = {242, -242};
    double[] oy = {140, 140};
    LocalPlanner.Command c =
        lp.plan(0, 0, 90, 0, 0, straight(), 0, 600, (x, y) -> 3000, ox, oy, 1, P);
    assertFalse(c.blocked(), c.toString());
    assertEquals(0, c.vel());
    assertTrue(c.rotVel() > 10, "turns left, the long way: " + c);
    // Without the point it takes the short way.
    c = lp.plan(0, 0, 90, 0, 0, straight(), 0, 600, (x, y) -> 3000, ox, oy, 0, P);
    assertTrue(c.rotVel() < -10, "turns right: " + c);
    // With a point on each side neither way is safe.
    c = lp.plan(0, 0, 90, 0, 0, straight(), 0, 600, (x, y) -> 3000, ox, oy, 2, P);
    assertTrue(c.blocked(), c.toString());
    assertEquals(0, c.rotVel());
  }

  @Test
  void stopsBeforeAnObstacleRightAhead() {
    LocalPlanner lp = new LocalPlanner();
    double[] ox = new double[41];
    double[] oy = new double[41];
    for (int i = 0; i <= 40; i++) {
      ox[i] = 270;
      oy[i] = -1000 + 50 * i;
    }
    LocalPlanner.Command c =
        lp.plan(0, 0, 0, 300, 0, straight(), 0, 600, (x, y) -> 3000, ox, oy, 41, P);
    assertTrue(c.blocked(), "a wall of obstacles across the way: " + c);
    assertEquals(0, c.vel());
  }

  @Test
  void neverChoosesAMotionThatCannotStopBeforeAnObstacle() {
    LocalPlanner lp = new LocalPlanner();
    for (double dist = 500; dist <= 1500; dist += 250) {
      double[] ox = {dist, dist, dist};
      double[] oy = {-50, 0, 50};
      for (double v0 = 0; v0 <= 400; v0 += 200) {
        LocalPlanner.Command c =
            lp.plan(0, 0, 0, v0, 0, straight(), 0, 600, (x, y) -> 3000, ox, oy, 3, P);
        assertFalse(c.blocked(), "room to manoeuvre at " + dist);
        // Braking at 300 mm/s/s after one more cycle must stop the front before the obstacle.
        double stop = c.vel() * c.vel() / (2 * 300) + c.vel() * 0.1;
        boolean headingAway = Math.abs(c.rotVel()) > 5;
        assertTrue(headingAway || 210 + stop < dist, "at " + dist + " from " + v0 + ": " + c);
      }
    }
    double[] area = lp.searchArea();
    assertTrue(area[2] > area[0] && area[3] > area[1]);
    // Too fast to stop before a close obstacle: the only safe answer is to brake.
    LocalPlanner.Command c =
        lp.plan(
            0,
            0,
            0,
            600,
            0,
            straight(),
            0,
            600,
            (x, y) -> 3000,
            new double[] {500},
            new double[] {0},
            1,
            P);
    assertTrue(c.blocked());
    assertEquals(0, c.vel());
  }
}
