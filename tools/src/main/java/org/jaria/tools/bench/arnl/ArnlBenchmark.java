package org.jaria.tools.bench.arnl;

import java.util.Locale;
import org.jaria.map.ArMap;

/**
 * The figures of the sonar localization and path planning ({@code ./jaria bench arnl}): filter
 * update time against particle count, tracking error on a long route, global localization success,
 * planning time and path quality on a 1000 × 1000 grid, and navigation success on random goals.
 * Every run uses fixed seeds, so the accuracy and success figures repeat exactly; only the times
 * depend on the computer. Headless; {@link #run(boolean)} returns the report as text.
 */
public final class ArnlBenchmark {

  private ArnlBenchmark() {}

  /**
   * Runs every benchmark.
   *
   * @param quick fewer repetitions (a minute instead of several), for a smoke test
   * @return the report, a few Markdown tables
   */
  public static String run(boolean quick) {
    StringBuilder sb = new StringBuilder();
    long t0 = System.nanoTime();
    sb.append("# JAria SonARNL benchmark").append(quick ? " (quick)" : "").append("\n\n");
    sb.append(
        String.format(
            Locale.ROOT,
            "Java %s on %d cores; simulated p3dx-sh, odometry error random(0.02, 0.02), lockstep.%n%n",
            System.getProperty("java.version"),
            Runtime.getRuntime().availableProcessors()));

    sb.append("## Localization update time (one core, thread CPU time)\n\n");
    sb.append(
        "One whole update (motion, sensor model, estimate, score, resampling) on a scan of the 16"
            + " sonars, of which `echoes` returned a usable echo.\n\n");
    sb.append("| particles | echoes | median ms | p95 ms |\n|---:|---:|---:|---:|\n");
    LocalizationBench.UpdateTime sonar2000 = null;
    for (LocalizationBench.UpdateTime u : LocalizationBench.updateTimes(quick)) {
      if (u.particles() == 2000) {
        sonar2000 = u;
      }
      sb.append(
          String.format(
              Locale.ROOT,
              "| %d | %d | %.3f | %.3f |%n",
              u.particles(),
              u.echoes(),
              u.medianMs(),
              u.p95Ms()));
    }

    int laps = quick ? 1 : 3;
    LocalizationBench.Tracking tr = LocalizationBench.tracking(laps);
    sb.append("\n## Tracking error (office map, ")
        .append(laps)
        .append(laps == 1 ? " lap" : " laps")
        .append(" of a 77 m route, 2000 particles)\n\n");
    sb.append("| distance m | RMSE mm | p95 mm | max mm | RMSE deg | p95 deg | max deg |\n");
    sb.append("|---:|---:|---:|---:|---:|---:|---:|\n");
    sb.append(
        String.format(
            Locale.ROOT,
            "| %.0f | %.0f | %.0f | %.0f | %.2f | %.2f | %.2f |%n",
            tr.metres(),
            tr.rmseMm(),
            tr.p95Mm(),
            tr.maxMm(),
            tr.rmseDeg(),
            tr.p95Deg(),
            tr.maxDeg()));

    int seeds = quick ? 8 : 50;
    sb.append(
        "\n## Global localization (no prior: random start pose in the free space, 20000"
            + " particles, then 60 s driving at up to 400 mm/s)\n\n");
    sb.append("| map | runs | within 250 mm / 0.25 rad | median s to converge | p95 s |\n");
    sb.append("|---|---:|---:|---:|---:|\n");
    LocalizationBench.Global sonarOffice = null;
    for (String name : new String[] {"columbia", "office"}) {
      ArMap map =
          name.equals("office")
              ? ArMap.loadBundled("office")
              : org.jaria.tools.examples.NavigateDemo.loadMap(columbiaPath());
      LocalizationBench.Global g = LocalizationBench.global(map, name, seeds);
      if (name.equals("office")) {
        sonarOffice = g;
      }
      sb.append(
          String.format(
              Locale.ROOT,
              "| %s | %d | %d (%.0f %%) | %.0f | %.0f |%n",
              g.map(),
              g.runs(),
              g.successes(),
              100.0 * g.successes() / g.runs(),
              g.medianSeconds(),
              g.p95Seconds()));
    }
    sb.append(LaserLocalizationBench.report(quick, sonar2000, tr, sonarOffice, laps, seeds));

    int pairs = quick ? 20 : 100;
    PlanningBench.Result p = PlanningBench.run(pairs);
    sb.append(
        "\n## Global planning (1000 x 1000 grid, 50 mm cells, generated building;"
            + " thread CPU time of A* and smoothing)\n\n");
    sb.append(
        "| pairs | median ms | p95 ms | length / shortest (mean) | (p95) | min clearance mm |"
            + " median min clearance mm |\n");
    sb.append("|---:|---:|---:|---:|---:|---:|---:|\n");
    sb.append(
        String.format(
            Locale.ROOT,
            "| %d | %.1f | %.1f | %.3f | %.3f | %.0f | %.0f |%n",
            p.pairs(),
            p.medianMs(),
            p.p95Ms(),
            p.meanLengthRatio(),
            p.p95LengthRatio(),
            p.minClearance(),
            p.medianMinClearance()));

    int navPairs = quick ? 10 : 100;
    NavigationBench.Result n = NavigationBench.run(navPairs);
    sb.append("\n## Navigation (office map, random start/goal pairs at least 5 m apart)\n\n");
    sb.append("| pairs | reached | mean time to goal s | mean final error mm |\n");
    sb.append("|---:|---:|---:|---:|\n");
    sb.append(
        String.format(
            Locale.ROOT,
            "| %d | %d (%.0f %%) | %.1f | %.0f |%n",
            n.pairs(),
            n.reached(),
            100.0 * n.reached() / n.pairs(),
            n.meanSeconds(),
            n.meanFinalError()));
    for (String f : n.failures()) {
      sb.append("\n- failed: ").append(f);
    }
    sb.append(
        String.format(
            Locale.ROOT, "%n%nTotal benchmark time %.0f s.%n", (System.nanoTime() - t0) / 1e9));
    return sb.toString();
  }

  /**
   * The Columbia map: {@code jaria.columbia} system property, else the reference copy in the source
   * tree (run from the repository root or a module directory).
   */
  static String columbiaPath() {
    String p = System.getProperty("jaria.columbia");
    if (p != null) {
      return p;
    }
    for (String base : new String[] {".", ".."}) {
      java.nio.file.Path c =
          java.nio.file.Path.of(
              base, "aria-core", "src", "test", "resources", "reference", "maps", "columbia.map");
      if (java.nio.file.Files.isRegularFile(c)) {
        return c.toString();
      }
    }
    throw new IllegalStateException(
        "columbia.map not found: run from the JAria source tree or set -Djaria.columbia=FILE");
  }

  /** Prints the report; {@code --quick} for the short version. */
  public static void main(String[] args) {
    boolean quick = args.length > 0 && args[0].equals("--quick");
    System.out.print(run(quick));
  }
}
