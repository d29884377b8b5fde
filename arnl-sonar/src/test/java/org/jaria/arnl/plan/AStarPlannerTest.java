package org.jaria.arnl.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.PriorityQueue;
import java.util.Random;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.junit.jupiter.api.Test;

class AStarPlannerTest {

  private static final double SQRT2 = Math.sqrt(2);

  @Test
  void findsTheCheapestPathOnRandomGrids() {
    Random rnd = new Random(3);
    AStarPlanner astar = new AStarPlanner();
    int compared = 0;
    for (int trial = 0; trial < 30; trial++) {
      int w = 20 + rnd.nextInt(30);
      int h = 20 + rnd.nextInt(30);
      GridSpec g = new GridSpec(0, 0, 100, w, h);
      boolean[] occ = new boolean[w * h];
      for (int k = 0; k < w * h / 12; k++) {
        occ[rnd.nextInt(w * h)] = true;
      }
      CostGrid grid = CostGrid.fromOccupancy(g, occ, 120, 400, 3);
      int start = randomFree(grid, rnd);
      int goal = randomFree(grid, rnd);
      int[] path = astar.plan(grid, start, goal);
      double best = dijkstra(grid, start, goal);
      if (Double.isInfinite(best)) {
        assertNull(path, "no path exists, so none may be found");
        continue;
      }
      assertNotNull(path, "a path exists");
      assertEquals(start, path[0]);
      assertEquals(goal, path[path.length - 1]);
      assertEquals(best, cost(grid, path), 1e-3 * best + 1e-6);
      compared++;
    }
    assertTrue(compared > 10);
  }

  private static int randomFree(CostGrid grid, Random rnd) {
    while (true) {
      int k = rnd.nextInt(grid.spec().size());
      if (grid.isFree(k)) {
        return k;
      }
    }
  }

  private static double cost(CostGrid grid, int[] path) {
    int w = grid.spec().width();
    double c = 0;
    for (int i = 1; i < path.length; i++) {
      int a = path[i - 1];
      int b = path[i];
      int di = Math.abs(a % w - b % w);
      int dj = Math.abs(a / w - b / w);
      assertTrue(di <= 1 && dj <= 1 && di + dj > 0, "steps are to a neighbour");
      c += (di + dj == 2 ? SQRT2 : 1) * grid.spec().res() * 0.5 * (grid.cost(a) + grid.cost(b));
    }
    return c;
  }

  /** Plain Dijkstra over the same moves (no corner cutting), for reference. */
  private static double dijkstra(CostGrid grid, int start, int goal) {
    int w = grid.spec().width();
    int h = grid.spec().height();
    double[] d = new double[w * h];
    Arrays.fill(d, Double.POSITIVE_INFINITY);
    d[start] = 0;
    PriorityQueue<double[]> q = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
    q.add(new double[] {0, start});
    while (!q.isEmpty()) {
      double[] top = q.poll();
      int c = (int) top[1];
      if (top[0] > d[c]) {
        continue;
      }
      int ci = c % w;
      int cj = c / w;
      for (int dj = -1; dj <= 1; dj++) {
        for (int di = -1; di <= 1; di++) {
          int ni = ci + di;
          int nj = cj + dj;
          if ((di == 0 && dj == 0) || ni < 0 || nj < 0 || ni >= w || nj >= h) {
            continue;
          }
          int nb = nj * w + ni;
          if (!grid.isFree(nb)) {
            continue;
          }
          if (di != 0 && dj != 0 && (!grid.isFree(cj * w + ni) || !grid.isFree(nj * w + ci))) {
            continue;
          }
          double step =
              (di != 0 && dj != 0 ? SQRT2 : 1)
                  * grid.spec().res()
                  * 0.5
                  * (grid.cost(c) + grid.cost(nb));
          if (d[c] + step < d[nb]) {
            d[nb] = d[c] + step;
            q.add(new double[] {d[nb], nb});
          }
        }
      }
    }
    return d[goal];
  }

  @Test
  void pathsKeepToTheMiddleOfACorridor() {
    ArMap office = ArMap.loadBundled("office");
    NavigationMap nav = NavigationMap.build(office, 100, 252, 1000, 4);
    CostGrid grid = nav.grid();
    int s = grid.spec().indexOf(2000, 9300);
    int g = grid.spec().indexOf(24000, 9700);
    int[] cells = new AStarPlanner().plan(grid, s, g);
    assertNotNull(cells);
    PlannedPath p = PathSmoother.smooth(cells, grid, 2000, 9300, 24000, 9700);
    double worst = 0;
    for (ArPose q : p.toPoses()) {
      if (q.x() > 4000 && q.x() < 22000) {
        worst = Math.max(worst, Math.abs(q.y() - 9500));
      }
    }
    assertTrue(worst < 120, "the corridor is 8500..10500; the path strayed " + worst + " mm");
    assertTrue(p.minClearance(grid) >= 750, "clearance " + p.minClearance(grid));
    assertEquals(22000, p.length(), 300);
  }

  @Test
  void forbiddenAreasAndClosedRoomsHaveNoPath() {
    ArMap office = ArMap.loadBundled("office");
    NavigationMap nav = NavigationMap.build(office, 100, 252, 1000, 4);
    CostGrid grid = nav.grid();
    assertTrue(nav.forbiddenAreaAt(13500, 6500).isPresent());
    assertTrue(!grid.isFree(grid.spec().indexOf(13500, 6500)), "forbidden area is an obstacle");
    // Inside the closed box in the lab (8500..14000, 1500..2300): unreachable from the corridor.
    int inside = grid.spec().indexOf(11000, 1900);
    int corridor = grid.spec().indexOf(5000, 9500);
    assertNull(new AStarPlanner().plan(grid, corridor, inside));
  }

  @Test
  void sensedObstaclesBlockCells() {
    ArMap office = ArMap.loadBundled("office");
    CostGrid grid = NavigationMap.build(office, 100, 252, 1000, 4).grid();
    CostGrid blocked = grid.withObstacles(new double[] {12000}, new double[] {9500}, 1);
    int k = grid.spec().indexOf(12000, 9600);
    assertTrue(grid.isFree(k));
    assertTrue(!blocked.isFree(k));
    assertTrue(blocked.clearance(k) <= 200);
  }
}
