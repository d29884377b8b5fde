package org.jaria.tools.bench.arnl;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jaria.arnl.mcl.LaserScans;
import org.jaria.arnl.mcl.LikelihoodField;
import org.jaria.arnl.mcl.MclFilter;
import org.jaria.arnl.mcl.PoseEstimate;
import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.devices.LaserSensor;

/**
 * Laser localization figures beside the sonar ones ({@link org.jaria.arnl.ArLocalizationTask}
 * against {@link org.jaria.arnl.ArSonarLocalizationTask}): update time, tracking error on the
 * office route and global localization success, in one table.
 */
final class LaserLocalizationBench {

  private LaserLocalizationBench() {}

  /** Laser model parameters of the task's defaults: cell size, sigma, floor; belief. */
  static LikelihoodField field(ArMap map) {
    return LikelihoodField.build(map, 50, 50, 0.1, 250);
  }

  static final double SENSOR_BELIEF = 0.05;

  /**
   * One whole update as {@code ArLocalizationTask} does it (motion, scan preparation, sensor model,
   * estimate, score, resampling) with 2000 particles on a 181-beam scan of the simulated office,
   * using every {@code beamStep}-th beam; thread CPU time.
   */
  static LocalizationBench.UpdateTime updateTime(int particles, int beamStep, boolean quick) {
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
      ranges = LaserSensor.of(r).ranges(-90, 1, 181);
      enc = sim.robot().getEncoderPose();
    } finally {
      LocalizationBench.close(sim);
    }
    double[] angles = new double[181];
    for (int i = 0; i < angles.length; i++) {
      angles[i] = -90 + i;
    }
    MclFilter f = new MclFilter(field(office), particles, 7);
    f.setSensorBelief(SENSOR_BELIEF);
    f.initGaussian(truth, particles, 100, 100, 3);
    List<Double> times = new ArrayList<>();
    int iterations = quick ? 150 : 400;
    int echoes = 0;
    ArPose from = enc;
    for (int it = 0; it < iterations + 100; it++) {
      ArPose to = new ArPose(from.x() + (it % 2 == 0 ? 5 : -5), from.y(), from.th());
      long t0 = BenchSupport.cpuNanos();
      f.motionUpdate(from, to);
      SonarScan s = LaserScans.prepare(angles, ranges, mount, to, 32000, beamStep);
      f.sensorUpdate(s);
      PoseEstimate e = f.estimateNear(truth);
      f.matchFraction(e.pose(), s, 150);
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
   * Sonar and laser side by side, as Markdown (the section of {@code jaria bench arnl}); the sonar
   * figures are those measured above it in the report.
   */
  static String report(
      boolean quick,
      LocalizationBench.UpdateTime sonarUpdate,
      LocalizationBench.Tracking sonarTracking,
      LocalizationBench.Global sonarGlobal,
      int laps,
      int seeds) {
    LocalizationBench.UpdateTime laser = updateTime(2000, 2, quick);
    LocalizationBench.UpdateTime laserAll = updateTime(2000, 1, quick);
    LocalizationBench.Tracking lt =
        LocalizationBench.tracking(laps, LocalizationBench.Sensor.LASER);
    LocalizationBench.Global lg =
        LocalizationBench.global(
            ArMap.loadBundled("office"), "office", seeds, LocalizationBench.Sensor.LASER);
    StringBuilder sb = new StringBuilder();
    sb.append(
        "\n## Sonar and laser localization side by side"
            + " (ArSonarLocalizationTask, ArLocalizationTask; default parameters)\n\n");
    sb.append(
        "Update: one whole update of 2000 particles, thread CPU time. Sonar: a scan of 16 sonars;"
            + " laser: a 181-beam scan (-90..90 by 1 degree), of which every 2nd beam is used"
            + " (LaserBeamStep 2), or all of them. Tracking: the office route above, odometry"
            + " error random(0.02, 0.02). Global: random start, no prior, 60 s of driving.\n\n");
    sb.append("| figure | sonar | laser |\n|---|---:|---:|\n");
    sb.append(
        row(
            "update median ms (p95)",
            String.format(
                Locale.ROOT,
                "%.3f (%.3f), %d echoes",
                sonarUpdate.medianMs(),
                sonarUpdate.p95Ms(),
                sonarUpdate.echoes()),
            String.format(
                Locale.ROOT,
                "%.3f (%.3f), %d beams",
                laser.medianMs(),
                laser.p95Ms(),
                laser.echoes())));
    sb.append(
        row(
            "update median ms (p95), all beams",
            "",
            String.format(
                Locale.ROOT,
                "%.3f (%.3f), %d beams",
                laserAll.medianMs(),
                laserAll.p95Ms(),
                laserAll.echoes())));
    sb.append(row("tracking RMSE mm", fmt(sonarTracking.rmseMm()), fmt(lt.rmseMm())));
    sb.append(row("tracking p95 / max mm", pair(sonarTracking), pair(lt)));
    sb.append(
        row(
            "tracking RMSE deg",
            String.format(Locale.ROOT, "%.2f", sonarTracking.rmseDeg()),
            String.format(Locale.ROOT, "%.2f", lt.rmseDeg())));
    sb.append(
        row(
            "mean along-track error mm",
            String.format(Locale.ROOT, "%+.0f", sonarTracking.meanAlongMm()),
            String.format(Locale.ROOT, "%+.0f", lt.meanAlongMm())));
    sb.append(row("global localization, office: within 250 mm", global(sonarGlobal), global(lg)));
    sb.append(
        row(
            "global localization: median s to converge",
            fmt(sonarGlobal.medianSeconds()),
            fmt(lg.medianSeconds())));
    return sb.toString();
  }

  private static String row(String name, String sonar, String laser) {
    return "| " + name + " | " + sonar + " | " + laser + " |\n";
  }

  private static String fmt(double v) {
    return String.format(Locale.ROOT, "%.0f", v);
  }

  private static String pair(LocalizationBench.Tracking t) {
    return String.format(Locale.ROOT, "%.0f / %.0f", t.p95Mm(), t.maxMm());
  }

  private static String global(LocalizationBench.Global g) {
    return String.format(
        Locale.ROOT,
        "%d of %d (%.0f %%)",
        g.successes(),
        g.runs(),
        100.0 * g.successes() / g.runs());
  }

  /** Prints the laser figures alone (quick with any argument): update time and tracking. */
  public static void main(String[] args) {
    boolean quick = args.length > 0;
    LocalizationBench.UpdateTime u = updateTime(2000, 2, quick);
    LocalizationBench.UpdateTime all = updateTime(2000, 1, quick);
    System.out.printf(
        Locale.ROOT,
        "laser update, 2000 particles: %d beams %.3f ms (p95 %.3f); %d beams %.3f ms (p95 %.3f)%n",
        u.echoes(),
        u.medianMs(),
        u.p95Ms(),
        all.echoes(),
        all.medianMs(),
        all.p95Ms());
    System.out.println(LocalizationBench.tracking(1, LocalizationBench.Sensor.LASER));
  }
}
