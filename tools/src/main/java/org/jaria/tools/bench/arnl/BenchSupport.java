package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.plan.AStarPlanner;
import org.jaria.arnl.plan.CostGrid;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PathSmoother;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArPose;

/** Small helpers shared by the benchmarks: statistics, free spots, driving by the true pose. */
final class BenchSupport {

  private BenchSupport() {}

  private static final java.lang.management.ThreadMXBean THREADS =
      java.lang.management.ManagementFactory.getThreadMXBean();

  /**
   * CPU time used by the calling thread so far, ns: timings made with it do not count the time the
   * thread waited while other programs had the processor (the wall clock does, and on a busy
   * computer that swamps what is measured). Falls back to the wall clock where the JVM cannot tell.
   */
  static long cpuNanos() {
    return THREADS.isCurrentThreadCpuTimeSupported()
        ? THREADS.getCurrentThreadCpuTime()
        : System.nanoTime();
  }

  /** The p-quantile (0..1) of the values, NaN if none. */
  static double quantile(List<Double> values, double p) {
    if (values.isEmpty()) {
      return Double.NaN;
    }
    double[] v = values.stream().mapToDouble(Double::doubleValue).toArray();
    Arrays.sort(v);
    int i = (int) Math.min(v.length - 1, Math.max(0, Math.ceil(p * v.length) - 1));
    return v[i];
  }

  /** The mean, NaN if none. */
  static double mean(List<Double> values) {
    return values.stream().mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
  }

  /** Root mean square, NaN if none. */
  static double rms(List<Double> values) {
    return Math.sqrt(values.stream().mapToDouble(x -> x * x).average().orElse(Double.NaN));
  }

  /** A random pose with at least {@code clearance} mm around it on {@code nav}'s grid. */
  static ArPose freePose(NavigationMap nav, double clearance, SplittableRandom rng) {
    CostGrid g = nav.grid();
    for (int tries = 0; tries < 1_000_000; tries++) {
      int k = rng.nextInt(g.spec().size());
      if (g.clearance(k) >= clearance) {
        double x = g.spec().centerX(k % g.spec().width());
        double y = g.spec().centerY(k / g.spec().width());
        if (nav.forbiddenAreaAt(x, y).isEmpty()) {
          return new ArPose(x, y, rng.nextDouble() * 360 - 180);
        }
      }
    }
    throw new IllegalStateException("no free spot on the map");
  }

  /** Waypoints every half metre along a planned path between two poses, or null if none. */
  static List<ArPose> route(NavigationMap nav, ArPose from, ArPose to) {
    CostGrid g = nav.grid();
    int[] cells =
        new AStarPlanner()
            .plan(g, g.spec().indexOf(from.x(), from.y()), g.spec().indexOf(to.x(), to.y()));
    if (cells == null) {
      return null;
    }
    PlannedPath p = PathSmoother.smooth(cells, g, from.x(), from.y(), to.x(), to.y());
    List<ArPose> out = new ArrayList<>();
    for (int i = 5; i < p.size(); i += 5) {
      out.add(new ArPose(p.x(i), p.y(i)));
    }
    out.add(to);
    return out;
  }
}
