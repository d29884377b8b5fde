package org.jaria.tools.bench;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.function.Supplier;
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
 *       driving around the bundled office map with a client connected, its laser off (target ≥
 *       2000×) and on (the client switches it on as ARIA's {@code ArSimulatedLaser} does: 181
 *       readings every SIP cycle);
 *   <li>the same for 10 and 100 robots in one open hall (target ≥ 20× at 100);
 *   <li>the cost of one sonar reading (a 7-ray cone) at 100, 1,000 and 10,000 map lines, next to a
 *       brute-force cast over every line, to show the spatial index keeps it nearly flat.
 * </ul>
 *
 * <p>A shared machine makes single short runs scatter widely, so every real-time factor is the
 * median of several runs, each of which keeps simulating until it has used a fixed amount of wall
 * time, and the table prints the spread (lowest and highest run) next to it. Figures are
 * measurements of this machine, printed, never asserted.
 */
public final class SimBenchmark {

  private SimBenchmark() {}

  /** Prints the table ({@code --quick}: a smoke run). */
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
   * @param wallSecondsPerRun wall-clock time each run keeps simulating for (at least)
   * @param runs runs per real-time factor (the median and the spread are taken over them; one more
   *     run before them warms the JIT up and is not counted)
   * @param readings sonar readings cast per map size
   */
  public record Settings(double wallSecondsPerRun, int runs, int readings) {
    /** The real benchmark: 7 runs of at least 1.5 s each per figure. */
    public static final Settings FULL = new Settings(1.5, 7, 200_000);

    /** A smoke run (tests): a fraction of a second per figure. */
    public static final Settings QUICK = new Settings(0.02, 2, 2_000);
  }

  /** The median and the range of the runs of one figure. */
  record Figure(double median, double min, double max) {
    /** Half the range relative to the median, %. */
    double spreadPercent() {
      return median > 0 ? 50 * (max - min) / median : 0;
    }

    static Figure of(double[] runs) {
      double[] r = runs.clone();
      Arrays.sort(r);
      int n = r.length;
      double median = n % 2 == 1 ? r[n / 2] : (r[n / 2 - 1] + r[n / 2]) / 2;
      return new Figure(median, r[0], r[n - 1]);
    }
  }

  /** Runs the benchmark with {@code s} and returns the table. */
  public static String run(Settings s) {
    StringBuilder sb = new StringBuilder();
    sb.append("JAria simulator benchmark (headless, virtual time)\n\n");
    sb.append(
        String.format(
            Locale.ROOT, "%-46s %10s %17s %7s%n", "world", "median", "lowest..highest", "spread"));
    row(
        sb,
        "1 p3dx-sh, 16 sonars, laser off, office map",
        figure(s, () -> SimWorld.bundled("office", SimOptions.defaults()), 1, false),
        "target >= 2000x");
    row(
        sb,
        "1 p3dx-sh, 16 sonars, laser on, office map",
        figure(s, () -> SimWorld.bundled("office", SimOptions.defaults()), 1, true),
        "181 readings / 100 ms");
    for (int n : new int[] {10, 100}) {
      row(
          sb,
          n + " p3dx-sh in one hall",
          figure(s, SimBenchmark::hall, n, false),
          n == 100 ? "target >= 20x" : "");
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
    sb.append(
            String.format(
                Locale.ROOT,
                "%n(real-time factor: median of %d runs of at least %.2f s wall each, after one"
                    + " warm-up run; spread = half the range over the median; a client per"
                    + " robot)%n",
                s.runs(),
                s.wallSecondsPerRun()))
        .append("(one sonar reading = a 7-ray cone, 5 m range, random origins and directions)\n");
    return sb.toString();
  }

  private static Figure figure(Settings s, Supplier<SimWorld> world, int n, boolean laser) {
    realTimeFactor(world.get(), n, "p3dx-sh", laser, s.wallSecondsPerRun()); // warm-up
    double[] r = new double[s.runs()];
    for (int i = 0; i < r.length; i++) {
      r[i] = realTimeFactor(world.get(), n, "p3dx-sh", laser, s.wallSecondsPerRun());
    }
    return Figure.of(r);
  }

  private static void row(StringBuilder sb, String what, Figure f, String note) {
    sb.append(
        String.format(
            Locale.ROOT,
            "%-46s %9.0fx %8.0f..%-8.0f %6.0f%%  %s%n",
            what,
            f.median(),
            f.min(),
            f.max(),
            f.spreadPercent(),
            note));
  }

  /**
   * Simulated seconds per wall second with {@code n} wandering robots, each with a client (which
   * switches the laser on if {@code laser}): after one simulated second of start-up, simulates in
   * one-second steps until {@code wallSeconds} of wall time have passed.
   */
  static double realTimeFactor(
      SimWorld world, int n, String model, boolean laser, double wallSeconds) {
    try (world) {
      List<ScriptedClient> clients = new ArrayList<>();
      for (int i = 0; i < n; i++) {
        clients.add(new ScriptedClient(world.addRobot(RobotOptions.of(model)), i + 1, laser));
      }
      world.addStepListener(
          () -> {
            for (ScriptedClient c : clients) {
              c.onTick();
            }
          });
      world.advance(Duration.ofSeconds(1));
      long budget = Math.round(wallSeconds * 1e9);
      long t0 = System.nanoTime();
      long simulated = 0;
      long wall;
      do {
        world.advance(Duration.ofSeconds(1));
        simulated++;
        wall = System.nanoTime() - t0;
      } while (wall < budget);
      return simulated * 1e9 / Math.max(1, wall);
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
