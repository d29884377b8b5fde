package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.arnl.plan.AStarPlanner;
import org.jaria.arnl.plan.CostGrid;
import org.jaria.arnl.plan.PathSmoother;
import org.jaria.arnl.plan.PlannedPath;

/**
 * Global planning on a 1000 × 1000 grid: a generated 50 m × 50 m building (10 × 10 rooms of 5 m
 * with one-metre doors and furniture) at 50 mm cells, random start and goal pairs.
 */
final class PlanningBench {

  private PlanningBench() {}

  /** Results. */
  record Result(
      int pairs,
      double medianMs,
      double p95Ms,
      double meanLengthRatio,
      double p95LengthRatio,
      double minClearance,
      double medianMinClearance) {}

  static final int SIZE = 1000;
  static final double RES = 50;

  /** The generated building, as an occupancy array. */
  static boolean[] building(long seed) {
    SplittableRandom rng = new SplittableRandom(seed);
    boolean[] occ = new boolean[SIZE * SIZE];
    int room = 100;
    // Outer walls and the room grid, two cells thick.
    for (int k = 0; k <= SIZE; k += room) {
      int line = Math.min(k, SIZE - 2);
      for (int t = 0; t < SIZE; t++) {
        for (int w = 0; w < 2; w++) {
          occ[(line + w) * SIZE + t] = true;
          occ[t * SIZE + line + w] = true;
        }
      }
    }
    // A one-metre door in most inner walls, at a random place along the wall.
    for (int r = 0; r < SIZE / room; r++) {
      for (int c = 0; c < SIZE / room; c++) {
        if (c + 1 < SIZE / room && rng.nextDouble() < 0.85) {
          int x = (c + 1) * room;
          int y0 = r * room + 10 + rng.nextInt(room - 40);
          for (int y = y0; y < y0 + 20; y++) {
            occ[y * SIZE + x] = false;
            occ[y * SIZE + x + 1] = false;
          }
        }
        if (r + 1 < SIZE / room && rng.nextDouble() < 0.85) {
          int y = (r + 1) * room;
          int x0 = c * room + 10 + rng.nextInt(room - 40);
          for (int x = x0; x < x0 + 20; x++) {
            occ[y * SIZE + x] = false;
            occ[(y + 1) * SIZE + x] = false;
          }
        }
        // Furniture: a box somewhere in the room.
        int bw = 10 + rng.nextInt(25);
        int bh = 10 + rng.nextInt(25);
        int bx = c * room + 15 + rng.nextInt(room - 30 - bw);
        int by = r * room + 15 + rng.nextInt(room - 30 - bh);
        for (int y = by; y < by + bh; y++) {
          for (int x = bx; x < bx + bw; x++) {
            occ[y * SIZE + x] = true;
          }
        }
      }
    }
    return occ;
  }

  static Result run(int pairs) {
    GridSpec spec = new GridSpec(0, 0, RES, SIZE, SIZE);
    boolean[] occ = building(42);
    CostGrid grid = CostGrid.fromOccupancy(spec, occ, 252, 1000, 4);
    CostGrid plain = CostGrid.fromOccupancy(spec, occ, 252, 253, 0);
    AStarPlanner astar = new AStarPlanner();
    AStarPlanner reference = new AStarPlanner();
    SplittableRandom rng = new SplittableRandom(7);
    List<Double> times = new ArrayList<>();
    List<Double> ratios = new ArrayList<>();
    List<Double> clearances = new ArrayList<>();
    // Warm up the JIT on a few plans first.
    for (int i = 0; i < 10; i++) {
      int s = free(grid, rng);
      int g = free(grid, rng);
      astar.plan(grid, s, g);
    }
    while (times.size() < pairs) {
      int s = free(grid, rng);
      int g = free(grid, rng);
      double sx = spec.centerX(s % SIZE);
      double sy = spec.centerY(s / SIZE);
      double gx = spec.centerX(g % SIZE);
      double gy = spec.centerY(g / SIZE);
      long t0 = BenchSupport.cpuNanos();
      int[] cells = astar.plan(grid, s, g);
      if (cells == null) {
        continue;
      }
      PlannedPath p = PathSmoother.smooth(cells, grid, sx, sy, gx, gy);
      times.add((BenchSupport.cpuNanos() - t0) / 1e6);
      double shortest = shortest(reference.plan(plain, s, g), plain);
      ratios.add(p.length() / shortest);
      clearances.add(p.minClearance(grid));
    }
    return new Result(
        pairs,
        BenchSupport.quantile(times, 0.5),
        BenchSupport.quantile(times, 0.95),
        BenchSupport.mean(ratios),
        BenchSupport.quantile(ratios, 0.95),
        BenchSupport.quantile(clearances, 0),
        BenchSupport.quantile(clearances, 0.5));
  }

  private static int free(CostGrid grid, SplittableRandom rng) {
    while (true) {
      int k = rng.nextInt(grid.spec().size());
      if (grid.isFree(k)) {
        return k;
      }
    }
  }

  /**
   * Length of the shortest collision-free path (same lethal radius, no clearance cost): the
   * shortest 8-connected path, then pulled taut — each point joined to the farthest later point it
   * can see through free cells.
   */
  static double shortest(int[] cells, CostGrid g) {
    GridSpec s = g.spec();
    double len = 0;
    int i = 0;
    while (i < cells.length - 1) {
      int j = cells.length - 1;
      while (j > i + 1 && !visible(g, cells[i], cells[j])) {
        j--;
      }
      int a = cells[i];
      int b = cells[j];
      len += s.res() * Math.hypot(a % s.width() - b % s.width(), a / s.width() - b / s.width());
      i = j;
    }
    return len;
  }

  private static boolean visible(CostGrid g, int a, int b) {
    int w = g.spec().width();
    int ax = a % w;
    int ay = a / w;
    int bx = b % w;
    int by = b / w;
    double x0 = ax;
    double y0 = ay;
    double x1 = bx;
    double y1 = by;
    int n = (int) Math.ceil(2 * Math.hypot(x1 - x0, y1 - y0));
    for (int k = 1; k < n; k++) {
      double t = (double) k / n;
      int c = (int) Math.round(y0 + (y1 - y0) * t) * w + (int) Math.round(x0 + (x1 - x0) * t);
      if (!g.isFree(c)) {
        return false;
      }
    }
    return true;
  }
}
