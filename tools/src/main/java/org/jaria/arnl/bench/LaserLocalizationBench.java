package org.jaria.arnl.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.jaria.arnl.mcl.LaserScans;
import org.jaria.arnl.mcl.LikelihoodField;
import org.jaria.arnl.mcl.MclFilter;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.devices.LaserSensor;

/**
 * Laser localization figures beside the sonar ones: the same Monte Carlo filter fed 181-beam laser
 * scans (−90..90° by 1°, ranges with 5 mm Gaussian noise, from the simulated robot's true pose)
 * through {@link LaserScans}.
 */
final class LaserLocalizationBench {

  private LaserLocalizationBench() {}

  /** How much each laser scan counts: 181 beams are far from independent. */
  static final double SENSOR_BELIEF = 0.05;

  /** Cell size, sigma, floor of the laser likelihood field. */
  static LikelihoodField field(ArMap map) {
    return LikelihoodField.build(map, 50, 50, 0.1, 250);
  }

  private static double[] angles() {
    double[] a = new double[181];
    for (int i = 0; i < a.length; i++) {
      a[i] = -90 + i;
    }
    return a;
  }

  private static double[] scan(LaserSensor sensor, SplittableRandom rng) {
    double[] r = sensor.ranges(-90, 1, 181);
    for (int i = 0; i < r.length; i++) {
      if (r[i] < sensor.maxRange()) {
        r[i] += 5 * gaussian(rng);
      }
    }
    return r;
  }

  private static double gaussian(SplittableRandom rng) {
    double u = 1 - rng.nextDouble();
    double v = rng.nextDouble();
    return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * v);
  }

  /** One whole update (motion, sensor model, estimate, resampling), timed. */
  static LocalizationBench.UpdateTime updateTime(int particles, boolean seeThrough, boolean quick) {
    ArMap office = ArMap.loadBundled("office");
    ArPose truth = new ArPose(15000, 12500, 60);
    SimulatedRobot sim = LocalizationBench.world(office, 1, truth);
    double[] ranges;
    ArPose enc;
    ArPose mount;
    try {
      sim.runMillis(500);
      SimRobot r = sim.sim();
      mount =
          new ArPose(r.getModel().getLaserX(), r.getModel().getLaserY(), r.getModel().getLaserTh());
      ranges = scan(LaserSensor.of(r), new SplittableRandom(3));
      enc = sim.robot().getEncoderPose();
    } finally {
      LocalizationBench.close(sim);
    }
    LikelihoodField field = field(office);
    MclFilter f = new MclFilter(field, particles, 7);
    f.setSensorBelief(SENSOR_BELIEF);
    if (!seeThrough) {
      f.setSeeThroughFactor(1);
    }
    f.initGaussian(truth, particles, 100, 100, 3);
    double[] angles = angles();
    List<Double> times = new ArrayList<>();
    int iterations = quick ? 150 : 400;
    int echoes = 0;
    ArPose from = enc;
    for (int it = 0; it < iterations + 100; it++) {
      ArPose to = new ArPose(from.x() + (it % 2 == 0 ? 5 : -5), from.y(), from.th());
      long t0 = BenchSupport.cpuNanos();
      f.motionUpdate(from, to);
      SonarScan s = LaserScans.prepare(angles, ranges, mount, enc, 32000, 1);
      f.sensorUpdate(s);
      f.estimateNear(truth);
      f.resampleIfNeeded();
      long t = BenchSupport.cpuNanos() - t0;
      if (it >= 100) {
        times.add(t / 1e6);
      }
      echoes = s.size();
      from = to;
    }
    return new LocalizationBench.UpdateTime(
        particles, echoes, BenchSupport.quantile(times, 0.5), BenchSupport.quantile(times, 0.95));
  }

  /**
   * Tracking error on the sonar benchmark's office route: the filter (2000 particles) updated every
   * 100 ms of robot time from odometry and a laser scan; error of its estimate against the truth.
   */
  static LaserTracking tracking(int laps) {
    ArMap office = ArMap.loadBundled("office");
    SimulatedRobot sim = LocalizationBench.world(office, 11, null);
    try {
      ArRobot robot = sim.robot();
      SimRobot simRobot = sim.sim();
      LaserSensor sensor = LaserSensor.of(simRobot);
      ArPose mount =
          new ArPose(
              simRobot.getModel().getLaserX(),
              simRobot.getModel().getLaserY(),
              simRobot.getModel().getLaserTh());
      SplittableRandom rng = new SplittableRandom(11);
      MclFilter f = new MclFilter(field(office), 2000, 11);
      f.setSensorBelief(SENSOR_BELIEF);
      sim.runMillis(500);
      f.initGaussian(simRobot.getTruePose(), 2000, 100, 100, 3);
      List<ArPose> route = BenchSupport.officeLaps(laps);
      BenchSupport.TruthDriver driver = new BenchSupport.TruthDriver(simRobot, route, 500);
      robot.addAction(driver, 50);
      double[] angles = angles();
      List<Double> mm = new ArrayList<>();
      List<Double> deg = new ArrayList<>();
      List<Double> along = new ArrayList<>();
      ArPose[] last = {robot.getEncoderPose(), simRobot.getTruePose()};
      // Each robot cycle, right after its SIP: in lockstep the world has not moved since the SIP
      // was sent, so the scan and the odometry describe the same moment (as a real driver gets
      // by time-stamping scans and interpolating odometry).
      robot.addUserTask(
          "laserLocalization",
          10,
          () -> {
            ArPose enc = robot.getEncoderPose();
            f.motionUpdate(last[0], enc);
            last[0] = enc;
            f.sensorUpdate(
                LaserScans.prepare(angles, scan(sensor, rng), mount, enc, sensor.maxRange(), 1));
            ArPose estimate = f.estimateNear(last[1]).pose();
            last[1] = estimate;
            f.resampleIfNeeded();
            ArPose truth = simRobot.getTruePose();
            mm.add(truth.findDistanceTo(estimate));
            double a = Math.toRadians(truth.th());
            if (robot.getVel() > 400) {
              along.add(
                  (estimate.x() - truth.x()) * Math.cos(a)
                      + (estimate.y() - truth.y()) * Math.sin(a));
            }
            deg.add(Math.abs(ArMath.subAngle(truth.th(), estimate.th())));
          });
      sim.runUntil(driver::done, java.time.Duration.ofMinutes(15L * laps));
      return new LaserTracking(
          new LocalizationBench.Tracking(
              robot.getOdometerDistance() / 1000,
              BenchSupport.rms(mm),
              BenchSupport.quantile(mm, 0.95),
              BenchSupport.quantile(mm, 1),
              BenchSupport.rms(deg),
              BenchSupport.quantile(deg, 0.95),
              BenchSupport.quantile(deg, 1)),
          BenchSupport.mean(along));
    } finally {
      LocalizationBench.close(sim);
    }
  }

  /**
   * Tracking error, and the mean signed error along the direction of travel while driving faster
   * than 400 mm/s (a lag or lead of the estimate shows here).
   */
  record LaserTracking(LocalizationBench.Tracking tracking, double meanAlongMm) {}

  /** Both, as Markdown (the section of {@code jaria bench arnl}). */
  static String report(boolean quick) {
    StringBuilder sb = new StringBuilder();
    sb.append("\n## Laser localization (same filter, 181-beam laser scans)\n\n");
    sb.append("| particles | beams used | see-through check | median ms | p95 ms |\n");
    sb.append("|---:|---:|---|---:|---:|\n");
    for (boolean through : new boolean[] {false, true}) {
      LocalizationBench.UpdateTime u = updateTime(2000, through, quick);
      sb.append(
          String.format(
              java.util.Locale.ROOT,
              "| %d | %d | %s | %.3f | %.3f |%n",
              u.particles(),
              u.echoes(),
              through ? "on" : "off",
              u.medianMs(),
              u.p95Ms()));
    }
    LaserTracking lt = tracking(1);
    LocalizationBench.Tracking tr = lt.tracking();
    sb.append(
        "\n| laser tracking | distance m | RMSE mm | p95 mm | max mm | RMSE deg | max deg | mean along-track mm |\n");
    sb.append("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    sb.append(
        String.format(
            java.util.Locale.ROOT,
            "| office, 1 lap, 2000 particles, every robot cycle | %.1f | %.0f | %.0f | %.0f | %.2f | %.2f | %+.0f |%n",
            tr.metres(),
            tr.rmseMm(),
            tr.p95Mm(),
            tr.maxMm(),
            tr.rmseDeg(),
            tr.maxDeg(),
            lt.meanAlongMm()));
    return sb.toString();
  }

  /** Prints {@link #report} (quick with any argument). */
  public static void main(String[] args) {
    System.out.println(report(args.length > 0));
  }
}
