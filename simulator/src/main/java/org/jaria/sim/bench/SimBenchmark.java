package org.jaria.sim.bench;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.jaria.sim.world.RayHit;
import org.jaria.sim.world.SegmentIndex;

/**
 * {@code ./jaria bench sim}: how fast the simulator runs, headless on virtual time.
 *
 * <ul>
 *   <li>real-time factor (simulated seconds per wall-clock second) of one P3-DX with 16 sonars
 *       driving around the bundled office map with a client connected (target ≥ 2000×);
 *   <li>the same for 10 and 100 robots in one open hall (target ≥ 20× at 100);
 *   <li>the cost of one sonar reading (a 7-ray cone) at 100, 1,000 and 10,000 map lines, next to a
 *       brute-force cast over every line, to show the spatial index keeps it nearly flat.
 * </ul>
 *
 * <p>Figures are measurements of this machine, printed, never asserted.
 */
public final class SimBenchmark {

  private SimBenchmark() {}

  /** Prints the table. */
  public static void main(String[] args) {
    boolean quick = args.length > 0 && args[0].equals("--quick");
    System.out.println(run(quick ? Settings.QUICK : Settings.FULL));
  }

  /** Runs the full benchmark and returns the table. */
  public static String run() {
    return run(Settings.FULL);
  }

  /**
   * How long each measurement runs.
   *
   * @param singleSeconds simulated seconds for the one-robot run
   * @param multiSeconds simulated seconds for the 10- and 100-robot runs
   * @param readings sonar readings cast per map size
   */
  public record Settings(int singleSeconds, int multiSeconds, int readings) {
    /** The real benchmark. */
    public static final Settings FULL = new Settings(600, 60, 200_000);

    /** A smoke run (tests): seconds instead of minutes. */
    public static final Settings QUICK = new Settings(5, 2, 2_000);
  }

  /** Runs the benchmark with {@code s} and returns the table. */
  public static String run(Settings s) {
    StringBuilder sb = new StringBuilder();
    sb.append("JAria simulator benchmark (headless, virtual time)\n\n");
    sb.append(String.format(Locale.ROOT, "%-46s %14s%n", "world", "real-time factor"));
    double one =
        median(
            () ->
                realTimeFactor(
                    SimWorld.bundled("office", SimOptions.defaults()),
                    1,
                    "p3dx-sh",
                    s.singleSeconds()));
    row(sb, "1 p3dx-sh, 16 sonars, office map", one, "target >= 2000x");
    for (int n : new int[] {10, 100}) {
      double f = median(() -> realTimeFactor(hall(), n, "p3dx-sh", s.multiSeconds()));
      row(sb, n + " p3dx-sh in one hall", f, n == 100 ? "target >= 20x" : "");
    }
    sb.append(
        String.format(
            Locale.ROOT,
            "%n%-12s %12s %16s %20s%n",
            "map lines",
            "cells",
            "ns per reading",
            "brute force ns/ray"));
    for (int lines : new int[] {100, 1_000, 10_000}) {
      rayRow(sb, lines, s.readings());
    }
    sb.append("\n(median of 3 runs, each with a client per robot; one sonar reading = a 7-ray")
        .append(" cone, 5 m range, random origins and directions)\n");
    return sb.toString();
  }

  /** The median of three runs (the first also warms the JIT up). */
  private static double median(java.util.function.DoubleSupplier run) {
    double[] r = {run.getAsDouble(), run.getAsDouble(), run.getAsDouble()};
    java.util.Arrays.sort(r);
    return r[1];
  }

  private static void row(StringBuilder sb, String what, double factor, String note) {
    sb.append(String.format(Locale.ROOT, "%-46s %13.0fx  %s%n", what, factor, note));
  }

  /** Simulated seconds per wall second with {@code n} wandering robots, each with a client. */
  static double realTimeFactor(SimWorld world, int n, String model, int seconds) {
    try (world) {
      List<ScriptedClient> clients = new ArrayList<>();
      for (int i = 0; i < n; i++) {
        clients.add(new ScriptedClient(world.addRobot(RobotOptions.of(model)), i + 1));
      }
      world.addStepListener(
          () -> {
            for (ScriptedClient c : clients) {
              c.onTick();
            }
          });
      world.advance(Duration.ofSeconds(Math.max(1, seconds / 10)));
      long t0 = System.nanoTime();
      world.advance(Duration.ofSeconds(seconds));
      long wall = System.nanoTime() - t0;
      return seconds * 1e9 / Math.max(1, wall);
    }
  }

  /** A 60 m × 60 m walled hall with a grid of pillars. */
  static SimWorld hall() {
    List<ArLineSegment> walls = new ArrayList<>();
    double size = 60_000;
    walls.add(new ArLineSegment(0, 0, size, 0));
    walls.add(new ArLineSegment(size, 0, size, size));
    walls.add(new ArLineSegment(size, size, 0, size));
    walls.add(new ArLineSegment(0, size, 0, 0));
    for (int i = 1; i < 6; i++) {
      for (int j = 1; j < 6; j++) {
        double cx = i * 10_000;
        double cy = j * 10_000;
        walls.add(new ArLineSegment(cx - 250, cy - 250, cx + 250, cy - 250));
        walls.add(new ArLineSegment(cx + 250, cy - 250, cx + 250, cy + 250));
        walls.add(new ArLineSegment(cx + 250, cy + 250, cx - 250, cy + 250));
        walls.add(new ArLineSegment(cx - 250, cy + 250, cx - 250, cy - 250));
      }
    }
    return SimWorld.ofLines(walls, new ArPose(30_000, 30_000, 0), SimOptions.defaults());
  }

  private static void rayRow(StringBuilder sb, int lines, int readings) {
    SplittableRandom rng = new SplittableRandom(lines);
    double area = 50_000;
    SegmentIndex.Builder b = SegmentIndex.builder();
    double[] seg = new double[lines * 4];
    for (int i = 0; i < lines; i++) {
      double x = rng.nextDouble() * area;
      double y = rng.nextDouble() * area;
      double a = rng.nextDouble() * 2 * Math.PI;
      double len = 500 + rng.nextDouble() * 2500;
      seg[4 * i] = x;
      seg[4 * i + 1] = y;
      seg[4 * i + 2] = x + len * Math.cos(a);
      seg[4 * i + 3] = y + len * Math.sin(a);
      b.addSegment(seg[4 * i], seg[4 * i + 1], seg[4 * i + 2], seg[4 * i + 3], RayHit.HitKind.LINE);
    }
    SegmentIndex index = b.build();
    RayHit hit = new RayHit();
    double[] ox = new double[readings];
    double[] oy = new double[readings];
    double[] th = new double[readings];
    for (int k = 0; k < readings; k++) {
      ox[k] = rng.nextDouble() * area;
      oy[k] = rng.nextDouble() * area;
      th[k] = rng.nextDouble() * 2 * Math.PI;
    }
    double sink = 0;
    for (int pass = 0; pass < 2; pass++) {
      long t0 = System.nanoTime();
      for (int k = 0; k < readings; k++) {
        for (int r = 0; r < 7; r++) {
          double a = th[k] + Math.toRadians((r / 6.0 - 0.5) * 30);
          hit.reset();
          index.cast(ox[k], oy[k], Math.cos(a), Math.sin(a), 5000, hit);
          sink += hit.distance > 5000 ? 0 : hit.distance;
        }
      }
      long perReading = (System.nanoTime() - t0) / readings;
      if (pass == 1) {
        int bruteRays = Math.max(100, readings / Math.max(1, lines / 100));
        long t1 = System.nanoTime();
        for (int k = 0; k < bruteRays; k++) {
          double dx = Math.cos(th[k % readings]);
          double dy = Math.sin(th[k % readings]);
          double best = 5000;
          for (int i = 0; i < lines; i++) {
            best = Math.min(best, raySeg(ox[k % readings], oy[k % readings], dx, dy, seg, i));
          }
          sink += best;
        }
        long brute = (System.nanoTime() - t1) / bruteRays;
        sb.append(
            String.format(
                Locale.ROOT,
                "%-12d %12d %16d %20d%n",
                lines,
                index.cellCount(),
                perReading,
                brute));
      }
    }
    if (sink == 42) {
      sb.append(' ');
    }
  }

  private static double raySeg(double ox, double oy, double dx, double dy, double[] s, int i) {
    double ex = s[4 * i + 2] - s[4 * i];
    double ey = s[4 * i + 3] - s[4 * i + 1];
    double den = dx * ey - dy * ex;
    if (Math.abs(den) < 1e-12) {
      return Double.POSITIVE_INFINITY;
    }
    double px = s[4 * i] - ox;
    double py = s[4 * i + 1] - oy;
    double t = (px * ey - py * ex) / den;
    double u = (px * dy - py * dx) / den;
    return t >= 0 && u >= 0 && u <= 1 ? t : Double.POSITIVE_INFINITY;
  }
}
