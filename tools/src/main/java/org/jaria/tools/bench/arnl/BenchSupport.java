package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.arnl.plan.AStarPlanner;
import org.jaria.arnl.plan.CostGrid;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.arnl.plan.PathSmoother;
import org.jaria.arnl.plan.PlannedPath;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimRobot;

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

  /**
   * Drives through waypoints steering by the simulator's true pose: the robot's motion for a
   * localization benchmark, independent of the localization being measured. It keeps its speed
   * through the waypoints (braking only for the last one, or to turn more than 20° on the spot), so
   * that the robot really drives at about {@code speed}.
   */
  /**
   * The office tracking route, {@code laps} times: along the corridors, into the rooms and back to
   * the start, so both localization benchmarks measure the same drive.
   */
  static List<ArPose> officeLaps(int laps) {
    List<ArPose> lap =
        List.of(
            new ArPose(9000, 9500),
            new ArPose(9000, 12000),
            new ArPose(9000, 15000),
            new ArPose(9000, 12000),
            new ArPose(9000, 9500),
            new ArPose(15000, 9500),
            new ArPose(15000, 15000),
            new ArPose(15000, 9500),
            new ArPose(26000, 9500),
            new ArPose(26250, 7000),
            new ArPose(26250, 6000),
            new ArPose(26250, 9500),
            new ArPose(1500, 9500));
    List<ArPose> route = new ArrayList<>();
    for (int i = 0; i < laps; i++) {
      route.addAll(lap);
    }
    return route;
  }

  static final class TruthDriver extends ArAction {
    private final ArActionDesired d = new ArActionDesired();
    private final SimRobot sim;
    private final List<ArPose> route;
    private final double[] remaining;
    private final double speed;
    private int next;

    TruthDriver(SimRobot sim, List<ArPose> route, double speed) {
      super("truthDriver");
      this.sim = sim;
      this.route = route;
      this.speed = speed;
      // remaining[i]: the distance from waypoint i on to the next one where the robot must stop:
      // the end, or a turn of more than 20 degrees, which it makes on the spot (as at the first
      // waypoint, since the robot may start facing anywhere).
      remaining = new double[route.size()];
      for (int i = route.size() - 2; i >= 1; i--) {
        double in = route.get(i - 1).findAngleTo(route.get(i));
        double out = route.get(i).findAngleTo(route.get(i + 1));
        boolean stop = Math.abs(ArMath.subAngle(out, in)) > 20;
        remaining[i] = stop ? 0 : remaining[i + 1] + route.get(i).findDistanceTo(route.get(i + 1));
      }
    }

    boolean done() {
      return next >= route.size();
    }

    @Override
    public ArActionDesired fire(ArActionDesired current) {
      d.reset();
      while (!done() && sim.getTruePose().findDistanceTo(route.get(next)) < 60) {
        next++;
      }
      if (done()) {
        d.setVel(0);
        d.setRotVel(0);
        return d;
      }
      ArPose p = sim.getTruePose();
      ArPose g = route.get(next);
      double off = ArMath.subAngle(p.findAngleTo(g), p.th());
      d.setRotVel(ArMath.clamp(2 * off, -60, 60));
      double toEnd = p.findDistanceTo(g) + remaining[next];
      double brake = Math.sqrt(2 * 250 * Math.max(0, toEnd - 40));
      d.setVel(Math.abs(off) > 20 ? 0 : Math.min(speed, brake) * Math.cos(Math.toRadians(off)));
      return d;
    }
  }
}
