package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The maps we ship must be sensible places to drive a Pioneer around. */
class BundledMapsTest {

  /** A P3-DX's radius: the clearance a robot centre needs from every wall. */
  private static final double ROBOT_RADIUS = 250;

  private static final double GRID = 100;

  /** Door centres of office.map: north side of the corridor (y 10500), then south (y 8500). */
  private static final double[][] OFFICE_DOORS = {
    {3000, 10500},
    {9000, 10500},
    {15000, 10500},
    {21000, 10500},
    {27000, 10500},
    {3750, 8500},
    {11250, 8500},
    {18750, 8500},
    {26250, 8500}
  };

  private static List<ArLineSegment> obstacles(ArMap m) {
    List<ArLineSegment> l = new ArrayList<>(m.getLines());
    for (ArMapObject o : m.getMapObjects()) {
      l.addAll(o.getFromToSegments());
    }
    return l;
  }

  private static boolean inForbiddenArea(ArMap m, double x, double y) {
    return m.getMapObjects().stream()
        .anyMatch(o -> o.type().equals("ForbiddenArea") && o.contains(x, y));
  }

  @ParameterizedTest
  @ValueSource(strings = {"office", "hall"})
  void goalsAreClearAndHomeIsAllowed(String name) {
    ArMap m = ArMap.loadBundled(name);
    List<ArLineSegment> obstacles = obstacles(m);
    List<ArMapObject> targets = new ArrayList<>(m.getGoals());
    m.findFirstMapObjectOfType("RobotHome").ifPresent(targets::add);
    m.findFirstMapObjectOfType("Dock").ifPresent(targets::add);
    assertTrue(m.getGoals().size() >= 6, name + " has few goals");
    for (ArMapObject g : targets) {
      double x = g.pose().x();
      double y = g.pose().y();
      for (ArLineSegment s : obstacles) {
        assertTrue(s.getDistToLine(x, y) >= 300, g.name() + " is within 300 mm of " + s);
      }
      assertFalse(inForbiddenArea(m, x, y), g.name() + " is in a forbidden area");
      assertTrue(m.getLineMinPos().x() < x && x < m.getLineMaxPos().x(), g.name() + " outside");
      assertTrue(m.getLineMinPos().y() < y && y < m.getLineMaxPos().y(), g.name() + " outside");
    }
    ArPose home = m.findHomePose().orElseThrow();
    assertFalse(inForbiddenArea(m, home.x(), home.y()));
    assertEquals("RobotHome", m.getMapObjects().get(0).type());
    assertTrue(m.getPoints().size() > 500, "laser-like points along the walls");
  }

  @Test
  void officeLayout() {
    ArMap m = ArMap.loadBundled("office");
    assertEquals(new ArPose(0, 0), m.getLineMinPos());
    assertEquals(new ArPose(30000, 20000), m.getLineMaxPos());
    List<String> rooms =
        List.of(
            "Room 101",
            "Room 102",
            "Room 103",
            "Room 104",
            "Room 105",
            "Kitchen",
            "Lab",
            "Room 106",
            "Meeting Room");
    for (String r : rooms) {
      assertTrue(m.findMapObject(r).orElseThrow().isGoal(), r);
    }
    ArPose home = m.findHomePose().orElseThrow();
    assertTrue(home.y() > 8500 && home.y() < 10500, "home is in the corridor");
    assertTrue(m.findFirstMapObjectOfType("Dock").isPresent());
    assertTrue(m.findFirstMapObjectOfType("ForbiddenArea").isPresent());
    assertTrue(m.findFirstMapObjectOfType("ForbiddenLine").isPresent());

    // Every door is open: a segment across the wall through its centre hits nothing, and the
    // gap between the wall ends on either side is 0.9 to 1.2 m.
    List<ArLineSegment> walls = m.getLines();
    for (double[] d : OFFICE_DOORS) {
      ArLineSegment across = new ArLineSegment(d[0], d[1] - 600, d[0], d[1] + 600);
      for (ArLineSegment w : walls) {
        assertFalse(across.intersects(w), "door at " + d[0] + "," + d[1] + " blocked by " + w);
      }
      double left = Double.NEGATIVE_INFINITY;
      double right = Double.POSITIVE_INFINITY;
      for (ArLineSegment w : walls) {
        if (w.y1() == d[1] && w.y2() == d[1]) {
          double lo = Math.min(w.x1(), w.x2());
          double hi = Math.max(w.x1(), w.x2());
          if (hi <= d[0]) {
            left = Math.max(left, hi);
          }
          if (lo >= d[0]) {
            right = Math.min(right, lo);
          }
        }
      }
      double width = right - left;
      assertTrue(width >= 900 && width <= 1200, "door at " + d[0] + " is " + width + " mm wide");
    }
  }

  @Test
  void hallLayout() {
    ArMap m = ArMap.loadBundled("hall");
    assertEquals(new ArPose(0, 0), m.getLineMinPos());
    assertEquals(new ArPose(20000, 15000), m.getLineMaxPos());
    assertTrue(m.getLines().size() > 4 * 6, "walls plus pillars and boxes");
  }

  @ParameterizedTest
  @ValueSource(strings = {"office", "hall"})
  void everyGoalIsReachableFromHome(String name) {
    ArMap m = ArMap.loadBundled(name);
    List<ArLineSegment> obstacles = obstacles(m);
    ArPose min = m.getLineMinPos();
    int nx = (int) Math.ceil((m.getLineMaxPos().x() - min.x()) / GRID);
    int ny = (int) Math.ceil((m.getLineMaxPos().y() - min.y()) / GRID);
    boolean[] free = new boolean[nx * ny];
    for (int j = 0; j < ny; j++) {
      for (int i = 0; i < nx; i++) {
        double x = min.x() + (i + 0.5) * GRID;
        double y = min.y() + (j + 0.5) * GRID;
        boolean ok = !inForbiddenArea(m, x, y);
        for (int k = 0; ok && k < obstacles.size(); k++) {
          ok = obstacles.get(k).getDistToLine(x, y) > ROBOT_RADIUS;
        }
        free[j * nx + i] = ok;
      }
    }
    ArPose home = m.findHomePose().orElseThrow();
    boolean[] seen = new boolean[free.length];
    ArrayDeque<Integer> queue = new ArrayDeque<>();
    int start = cell(home, min, nx);
    assertTrue(free[start], "home cell is free");
    seen[start] = true;
    queue.add(start);
    while (!queue.isEmpty()) {
      int c = queue.poll();
      int ci = c % nx;
      int cj = c / nx;
      int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (int[] s : steps) {
        int i = ci + s[0];
        int j = cj + s[1];
        if (i >= 0 && j >= 0 && i < nx && j < ny && free[j * nx + i] && !seen[j * nx + i]) {
          seen[j * nx + i] = true;
          queue.add(j * nx + i);
        }
      }
    }
    int behindWalls = 0;
    for (ArMapObject g : m.getMapObjects()) {
      if (g.isGoal() || g.type().equals("Dock")) {
        assertTrue(seen[cell(g.pose(), min, nx)], g.name() + " cannot be reached from home");
        ArLineSegment direct = new ArLineSegment(home, g.pose());
        if (m.getLines().stream().anyMatch(direct::intersects)) {
          behindWalls++;
        }
      }
    }
    if (name.equals("office")) {
      assertTrue(behindWalls >= 8, "goals behind doorways: " + behindWalls);
    }
  }

  private static int cell(ArPose p, ArPose min, int nx) {
    int i = (int) ((p.x() - min.x()) / GRID);
    int j = (int) ((p.y() - min.y()) / GRID);
    return j * nx + i;
  }
}
