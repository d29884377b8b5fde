package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.ArBaseLocalizationTask;
import org.jaria.arnl.ArLocalizationTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.arnl.LocalizationState;
import org.jaria.arnl.TrueRoute;
import org.jaria.arnl.mcl.LikelihoodField;
import org.jaria.arnl.mcl.MclFilter;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.arnl.plan.NavigationMap;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.range.ArSensorReading;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/** Localization figures: update time, tracking error on a long route, global localization. */
final class LocalizationBench {

  private LocalizationBench() {}

  /** Time of one filter update. */
  record UpdateTime(int particles, int echoes, double medianMs, double p95Ms) {}

  /**
   * Tracking error along a route; {@code meanAlongMm} is the mean signed error along the direction
   * of travel while driving faster than 400 mm/s (a lag or lead of the estimate shows there).
   */
  record Tracking(
      double metres,
      double rmseMm,
      double p95Mm,
      double maxMm,
      double rmseDeg,
      double p95Deg,
      double maxDeg,
      double meanAlongMm) {}

  /** Global localization results. */
  record Global(String map, int runs, int successes, double medianSeconds, double p95Seconds) {}

  /** Which sensor localizes the robot. */
  enum Sensor {
    /** The 16 sonars, {@link ArSonarLocalizationTask}. */
    SONAR,
    /** A simulated 181-beam laser, {@link ArLocalizationTask}. */
    LASER;

    /** A synchronous localization task of this kind on {@code sim}'s robot. */
    ArBaseLocalizationTask task(SimulatedRobot sim, ArMap map, long seed) {
      ArRobot robot = sim.robot();
      if (this == SONAR) {
        return ArSonarLocalizationTask.builder(robot, map)
            .mode(ArBaseLocalizationTask.UpdateMode.SYNCHRONOUS)
            .seed(seed)
            .build();
      }
      ArSimulatedLaser laser = new ArSimulatedLaser();
      robot.addRangeDevice(laser);
      return ArLocalizationTask.builder(robot, map)
          .laser(laser)
          .mode(ArBaseLocalizationTask.UpdateMode.SYNCHRONOUS)
          .seed(seed)
          .build();
    }
  }

  static SimulatedRobot world(ArMap map, long seed, ArPose start) {
    SimWorld world =
        SimWorld.create(
            map,
            SimOptions.builder()
                .seed(seed)
                .odometryError(OdometryError.random(0.02, 0.02))
                .build());
    RobotOptions o = RobotOptions.of("p3dx-sh");
    SimRobot r = world.addRobot(start == null ? o : o.withStartPose(start));
    SimulatedRobot sim = SimulatedRobot.connect(world, r);
    sim.robot().addRangeDevice(new ArSonarDevice());
    sim.robot().enableMotors();
    return sim;
  }

  static void close(SimulatedRobot sim) {
    sim.close();
    sim.world().close();
  }

  /**
   * One update as the task does it (motion, scan preparation, weighting, estimate, score,
   * resampling), timed at each particle count, on real sonar readings from the simulator.
   */
  static List<UpdateTime> updateTimes(boolean quick) {
    ArMap office = ArMap.loadBundled("office");
    ArPose truth = new ArPose(15000, 12500, 60);
    SimulatedRobot sim = world(office, 1, truth);
    List<ArSensorReading> readings = new ArrayList<>();
    ArPose enc;
    try {
      sim.runMillis(1500);
      ArRobot robot = sim.robot();
      for (int i = 0; i < robot.getNumSonar(); i++) {
        readings.add(robot.getSonarReading(i));
      }
      enc = robot.getEncoderPose();
    } finally {
      close(sim);
    }
    LikelihoodField field = LikelihoodField.build(office, 50, 100, 0.2, 250);
    List<UpdateTime> out = new ArrayList<>();
    int iterations = quick ? 150 : 400;
    for (int n : new int[] {500, 2000, 5000, 20000}) {
      MclFilter f = new MclFilter(field, n, 7);
      f.setSensorBelief(0.4);
      ArPose local = new ArPose(truth.x(), truth.y(), truth.th());
      f.initGaussian(local, n, 100, 100, 3);
      List<Double> times = new ArrayList<>();
      int echoes = 0;
      ArPose from = enc;
      for (int it = 0; it < iterations + 100; it++) {
        ArPose to = new ArPose(from.x() + (it % 2 == 0 ? 5 : -5), from.y(), from.th());
        long t0 = BenchSupport.cpuNanos();
        f.motionUpdate(from, to);
        SonarScan scan = SonarScan.prepare(readings, enc, 150, 4500, 15, 7);
        f.sensorUpdate(scan);
        PoseEstimate e = f.estimateNear(local);
        f.matchFraction(e.pose(), scan, 250);
        f.resampleIfNeeded();
        long t = BenchSupport.cpuNanos() - t0;
        if (it >= 100) {
          times.add(t / 1e6);
        }
        echoes = scan.size();
        from = to;
      }
      out.add(new UpdateTime(n, echoes, BenchSupport.quantile(times, 0.5), quantile95(times)));
    }
    return out;
  }

  private static double quantile95(List<Double> v) {
    return BenchSupport.quantile(v, 0.95);
  }

  /** Tracking error on laps of a route through the office (77 m a lap), default parameters. */
  static Tracking tracking(int laps) {
    return tracking(laps, Sensor.SONAR);
  }

  /** As {@link #tracking(int)}, localizing with {@code sensor}. */
  static Tracking tracking(int laps, Sensor sensor) {
    return tracking(laps, sensor, 11);
  }

  /** As {@link #tracking(int, Sensor)}, with the world's and the filter's seed. */
  static Tracking tracking(int laps, Sensor sensor, long seed) {
    ArMap office = ArMap.loadBundled("office");
    SimulatedRobot sim = world(office, seed, null);
    try {
      ArRobot robot = sim.robot();
      ArBaseLocalizationTask loc = sensor.task(sim, office, seed);
      sim.runMillis(1000);
      loc.localizeRobotAtHomeBlocking();
      TrueRoute driver = TrueRoute.keepingSpeed(sim.sim(), TrueRoute.officeLaps(laps), 500);
      robot.addAction(driver, 50);
      List<Double> mm = new ArrayList<>();
      List<Double> deg = new ArrayList<>();
      List<Double> along = new ArrayList<>();
      robot.addUserTask(
          "measure",
          10,
          () -> {
            ArPose t = sim.sim().getTruePose();
            ArPose e = robot.getPose();
            mm.add(t.findDistanceTo(e));
            deg.add(Math.abs(ArMath.subAngle(t.th(), e.th())));
            if (robot.getVel() > 400) {
              double a = Math.toRadians(t.th());
              along.add((e.x() - t.x()) * Math.cos(a) + (e.y() - t.y()) * Math.sin(a));
            }
          });
      sim.runUntil(driver::done, java.time.Duration.ofMinutes(15L * laps));
      loc.close();
      return new Tracking(
          robot.getOdometerDistance() / 1000,
          BenchSupport.rms(mm),
          BenchSupport.quantile(mm, 0.95),
          BenchSupport.quantile(mm, 1),
          BenchSupport.rms(deg),
          BenchSupport.quantile(deg, 0.95),
          BenchSupport.quantile(deg, 1),
          BenchSupport.mean(along));
    } finally {
      close(sim);
    }
  }

  /**
   * Global localization from a uniform start: the robot starts at a random free pose and drives (by
   * its true pose) towards a random far goal; success if after 60 s the estimate is within 250 mm
   * and 0.25 rad. The time to converge is when the error last entered those bounds.
   */
  static Global global(ArMap map, String name, int runs) {
    return global(map, name, runs, Sensor.SONAR);
  }

  /** As {@link #global(ArMap, String, int)}, localizing with {@code sensor}. */
  static Global global(ArMap map, String name, int runs, Sensor sensor) {
    NavigationMap nav = NavigationMap.build(map, 100, 300, 1000, 4);
    ArPose home = map.findHomePose().orElse(ArPose.ORIGIN);
    int successes = 0;
    List<Double> times = new ArrayList<>();
    for (int seed = 1; seed <= runs; seed++) {
      SplittableRandom rng = new SplittableRandom(1000 + seed);
      ArPose start;
      List<ArPose> route;
      while (true) {
        start = BenchSupport.freePose(nav, 500, rng);
        ArPose goal = BenchSupport.freePose(nav, 500, rng);
        if (start.findDistanceTo(goal) < 12000 || BenchSupport.route(nav, home, start) == null) {
          continue;
        }
        route = BenchSupport.route(nav, start, goal);
        if (route != null) {
          break;
        }
      }
      SimulatedRobot sim = world(map, seed, start);
      try {
        ArRobot robot = sim.robot();
        ArBaseLocalizationTask loc = sensor.task(sim, map, seed);
        loc.getParams().setAdjustNumSamples(true);
        sim.runMillis(500);
        loc.startGlobalLocalization();
        robot.addAction(TrueRoute.keepingSpeed(sim.sim(), route, 400), 50);
        double lastOut = 0;
        boolean ok = false;
        for (int s = 1; s <= 60; s++) {
          sim.runMillis(1000);
          ArPose t = sim.sim().getTruePose();
          ArPose e = robot.getPose();
          ok =
              loc.getState() != LocalizationState.LOCALIZATION_INIT_COMPUTING
                  && t.findDistanceTo(e) < 250
                  && Math.abs(ArMath.subAngle(t.th(), e.th())) < Math.toDegrees(0.25);
          if (!ok) {
            lastOut = s;
          }
        }
        if (ok) {
          successes++;
          times.add(lastOut);
        }
        loc.close();
      } finally {
        close(sim);
      }
    }
    return new Global(
        name,
        runs,
        successes,
        BenchSupport.quantile(times, 0.5),
        BenchSupport.quantile(times, 0.95));
  }
}
