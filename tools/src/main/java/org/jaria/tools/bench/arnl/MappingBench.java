package org.jaria.tools.bench.arnl;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.jaria.arnl.TrueRoute;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArLaserLogger;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.MapBuildException;
import org.jaria.mapping.MapBuilder;
import org.jaria.mapping.MapBuilderParams;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;

/**
 * {@code jaria bench mapping}: drives the simulator (odometry error on, the true path and map known
 * exactly) through a map with the laser logging as sickLogger does, builds the map from the log,
 * and compares: the path with the true one, the map's points with the true walls, the true walls
 * the laser saw with the map; build time against the log's duration, and memory. Then the robot
 * localizes with the laser on the built map and drives to five goals ({@link MappingNavigation}).
 */
public final class MappingBench {

  private MappingBench() {}

  /** A recorded drive: the log, the true laser pose and the true laser hits at every scan. */
  record Drive(String log, List<ArPose> trueLaser, List<double[]> trueHits, double seconds) {}

  /** The figures of one map. */
  record Row(
      String map,
      int scans,
      double logSeconds,
      double pathRms,
      double pathMax,
      double nearWalls,
      double offWalls,
      double covered,
      double buildCpuSeconds,
      double buildWallSeconds,
      long pointBytes,
      long heapMb,
      int loopClosures,
      MappingNavigation.Result nav) {}

  /** Drives {@code route} on {@code truth} from its home and logs it. */
  static Drive drive(ArMap truth, List<ArPose> route, long seed) {
    SimulatedRobot sim =
        LocalizationBench.world(truth, seed, truth.findHomePose().orElse(ArPose.ORIGIN));
    try {
      ArSimulatedLaser laser = new ArSimulatedLaser();
      sim.robot().addRangeDevice(laser);
      sim.runMillis(1000);
      StringWriter out = new StringWriter();
      List<ArPose> trueLaser = new ArrayList<>();
      List<double[]> hits = new ArrayList<>();
      SimRobot r = sim.sim();
      ArLaserLogger logger = new ArLaserLogger(sim.robot(), laser, 300, 25, out, "bench");
      logger.addEntryCB(
          e -> {
            if (e instanceof LoggedScan) {
              org.jaria.sim.SimLaserScan t = r.getLaserScan();
              trueLaser.add(t.origin());
              hits.add(hitsOf(t));
            }
          });
      TrueRoute d = TrueRoute.keepingSpeed(r, route, 500);
      sim.robot().addAction(d, 50);
      long t0 = sim.world().getClock().nanoTime();
      sim.runUntil(d::done, Duration.ofMinutes(90));
      sim.runMillis(500);
      logger.close();
      double seconds = (sim.world().getClock().nanoTime() - t0) / 1e9;
      return new Drive(out.toString(), trueLaser, hits, seconds);
    } finally {
      LocalizationBench.close(sim);
    }
  }

  /** The true laser's hit points (x, y pairs) within the map range. */
  private static double[] hitsOf(org.jaria.sim.SimLaserScan t) {
    double[] xy = new double[2 * t.size()];
    int n = 0;
    ArPose o = t.origin();
    double range = MapBuilderParams.DEFAULTS.mapRangeMm();
    for (int k = 0; k < t.size(); k++) {
      int rr = t.range(k);
      if (rr > 0 && rr <= range) {
        double a = Math.toRadians(o.th() + t.startDeg() + k * t.incrementDeg());
        xy[n++] = o.x() + rr * Math.cos(a);
        xy[n++] = o.y() + rr * Math.sin(a);
      }
    }
    return java.util.Arrays.copyOf(xy, n);
  }

  /** Builds the drive's log, timed (thread CPU and wall). */
  static Row measure(String name, ArMap truth, Drive d, boolean navigate) {
    System.gc();
    Runtime rt = Runtime.getRuntime();
    long heap0 = rt.totalMemory() - rt.freeMemory();
    long cpu0 = BenchSupport.cpuNanos();
    long wall0 = System.nanoTime();
    BuiltMap m;
    long pointBytes;
    try (ScanLogReader reader = new ScanLogReader(new StringReader(d.log()), name)) {
      MapBuilder b = new MapBuilder(reader.header(), MapBuilderParams.DEFAULTS);
      for (ScanLogEntry e = reader.next(); e != null; e = reader.next()) {
        b.add(e);
      }
      pointBytes = b.pointBytes();
      m = b.finish();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    } catch (MapBuildException e) {
      throw new IllegalStateException(name + ": " + e.getMessage(), e);
    }
    double cpu = (BenchSupport.cpuNanos() - cpu0) / 1e9;
    double wall = (System.nanoTime() - wall0) / 1e9;
    long heap = Math.max(0, rt.totalMemory() - rt.freeMemory() - heap0);
    ArPose mount = new ArPose(21, 0, 0);
    ArPose toTruth = TruthCompare.toTruth(m, d.trueLaser(), mount);
    double[] path = TruthCompare.pathError(m.trajectory(), d.trueLaser(), toTruth, mount);
    TruthCompare walls = TruthCompare.of(truth);
    double[] near = walls.nearShares(m, toTruth);
    double covered = walls.coverage(m, toTruth, d.trueHits());
    MappingNavigation.Result nav =
        navigate ? MappingNavigation.run(truth, m.toArMap(), toTruth, d.trueLaser(), 5, 77) : null;
    return new Row(
        name,
        m.trajectory().size(),
        d.seconds(),
        path[0],
        path[1],
        near[0],
        near[1],
        covered,
        cpu,
        wall,
        pointBytes,
        heap >> 20,
        m.stats().loopClosures(),
        nav);
  }

  /** A tour of {@code n} random reachable places from home and back, as waypoints. */
  static List<ArPose> tour(ArMap map, int n, long seed) {
    NavigationMap nav = NavigationMap.build(map, 100, 300, 1000, 4);
    ArPose home = map.findHomePose().orElse(ArPose.ORIGIN);
    SplittableRandom rng = new SplittableRandom(seed);
    List<ArPose> route = new ArrayList<>();
    ArPose at = home;
    for (int i = 0; i < n; i++) {
      for (int tries = 0; tries < 200; tries++) {
        ArPose next = BenchSupport.freePose(nav, 600, rng);
        List<ArPose> leg =
            next.findDistanceTo(at) > 4000 ? BenchSupport.route(nav, at, next) : null;
        if (leg != null) {
          route.addAll(leg);
          at = next;
          break;
        }
      }
    }
    List<ArPose> back = BenchSupport.route(nav, at, home);
    if (back != null) {
      route.addAll(back);
    }
    return route;
  }

  /** The benchmark's table (quick: one office lap, no columbia). */
  public static String run(boolean quick) {
    List<Row> rows = new ArrayList<>();
    ArMap office = ArMap.loadBundled("office");
    rows.add(
        measure(
            quick ? "office, 1 lap" : "office, 3 laps",
            office,
            drive(office, TrueRoute.officeLaps(quick ? 1 : 3), 11),
            true));
    ArMap hall = ArMap.loadBundled("hall");
    rows.add(measure("hall", hall, drive(hall, tour(hall, 5, 3), 3), true));
    if (!quick) {
      ArMap columbia = ArMap.loadBundled("columbia");
      rows.add(measure("columbia", columbia, drive(columbia, tour(columbia, 6, 5), 5), true));
    }
    ArMap unseen = UnseenMap.generate(20261127);
    rows.add(measure("unseen (generated)", unseen, drive(unseen, tour(unseen, 6, 9), 9), true));
    return table(rows);
  }

  static String table(List<Row> rows) {
    StringBuilder sb = new StringBuilder();
    sb.append(
        "## Mapping: laser scan log to map (simulator, odometry error random(0.02, 0.02),"
            + " ArLaserLogger every 300 mm / 25 degrees)\n\n");
    sb.append(
        "Path error: the corrected laser pose of every scan against the true one. Points: the"
            + " share of the built map's points within 50 mm of a true wall (a map line, or a map"
            + " point as the simulator blocks it), and 50-300 mm off one (a doubled wall would be"
            + " there). Covered: the share of true walls the laser saw (within 12 m) that the map"
            + " has a point within 50 mm of. Build: thread CPU time (wall time on this busy"
            + " machine) against the log's duration; memory: scan points held, and heap growth"
            + " over the build. Navigation: laser localization (ArLocalizationTask) on the built"
            + " map, in the true world, to 5 random places the logging drive passed"
            + " (ArPathPlanningTask), by routes on the built map that stay within 1.5 m of the"
            + " logging drive.\n\n");
    sb.append(
        "| map | scans | log s | path RMS / max mm | points within 50 mm | 50-300 mm off |"
            + " walls covered | build CPU s (wall) | log/build | points held, heap | loops |"
            + " goals reached, mean error mm (each goal) |\n");
    sb.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (Row r : rows) {
      sb.append(
          String.format(
              Locale.ROOT,
              "| %s | %d | %.0f | %.0f / %.0f | %.1f %% | %.2f %% | %.1f %% | %.2f (%.2f) | %.0fx"
                  + " | %d kB, %d MB | %d | %s |\n",
              r.map(),
              r.scans(),
              r.logSeconds(),
              r.pathRms(),
              r.pathMax(),
              100 * r.nearWalls(),
              100 * r.offWalls(),
              100 * r.covered(),
              r.buildCpuSeconds(),
              r.buildWallSeconds(),
              r.logSeconds() / r.buildCpuSeconds(),
              r.pointBytes() >> 10,
              r.heapMb(),
              r.loopClosures(),
              r.nav() == null
                  ? "-"
                  : String.format(
                      Locale.ROOT,
                      "%d of %d, %.0f (%s)",
                      r.nav().reached(),
                      r.nav().goals(),
                      r.nav().meanErrorMm(),
                      String.join(", ", r.nav().perGoal()))));
    }
    return sb.toString();
  }

  /** Prints the table (quick with any argument). */
  public static void main(String[] args) {
    System.out.println(run(args.length > 0));
  }
}
