package org.jaria.tools.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.laser.log.ScanLogFormatException;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.LogMapping;
import org.jaria.mapping.MapBuildException;
import org.jaria.mapping.MapBuilderParams;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jaria map build SCANS.2d -o lab.map}: a map from a laser scan log. */
@Command(
    name = "build",
    description = {
      "Build an ARIA .map from a laser scan log (.2d, from 'jaria laser log' or sickLogger):"
          + " scan matching, loop closure, points thinned to the resolution, lines along the"
          + " walls, the start as RobotHome and logged goals, in the log's own frame.",
      "Example: jaria map build lab.2d -o lab.map"
    })
final class MapBuildCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Parameters(paramLabel = "SCANS.2d", description = "The laser scan log.")
  Path log;

  @Option(
      names = {"-o", "--output"},
      paramLabel = "FILE",
      description = "The map to write (default: the log's name with .map).")
  Path out;

  @Option(
      names = "--resolution",
      paramLabel = "MM",
      description = "Point spacing of the map, mm (default: ${DEFAULT-VALUE}).")
  int resolution = MapBuilderParams.DEFAULTS.resolutionMm();

  @Option(
      names = "--map-range",
      paramLabel = "MM",
      description = "Readings up to this range become map points, mm (default: ${DEFAULT-VALUE}).")
  double mapRange = MapBuilderParams.DEFAULTS.mapRangeMm();

  @Override
  public Integer call() {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    Path target = this.out != null ? this.out : defaultOutput(log);
    MapBuilderParams params;
    try {
      params = MapBuilderParams.DEFAULTS.withResolution(resolution).withMapRange(mapRange);
    } catch (IllegalArgumentException e) {
      err.println(e.getMessage());
      return 2;
    }
    long t0 = System.nanoTime();
    int[] shown = {-1};
    LogMapping.Result r;
    try {
      r =
          LogMapping.build(
              log,
              params,
              p -> {
                int tenth = (int) Math.floor(p.fraction() * 10);
                if (tenth > shown[0]) {
                  shown[0] = tenth;
                  out.printf(
                      Locale.ROOT,
                      "%3.0f %%  %d scans, %d poses, %d loop closures%n",
                      100 * p.fraction(),
                      p.scansRead(),
                      p.poses(),
                      p.loopClosures());
                  out.flush();
                }
              });
    } catch (NoSuchFileException e) {
      err.println("no such log: " + log);
      return 1;
    } catch (ScanLogFormatException | MapBuildException e) {
      err.println(e.getMessage());
      return 1;
    } catch (IOException e) {
      err.println("cannot read " + log + ": " + e.getMessage());
      return 1;
    }
    BuiltMap m = r.map();
    try {
      m.writeFile(target);
    } catch (IOException e) {
      err.println("cannot write " + target + ": " + e.getMessage());
      return 1;
    }
    double seconds = (System.nanoTime() - t0) / 1e9;
    out.println(m.stats().summary());
    if (!r.log().skippedSummary().isEmpty()) {
      out.println("log: " + r.log().skippedSummary());
    }
    out.printf(
        Locale.ROOT,
        "wrote %s: %d points, %d lines, %d goals (%.1f s)%n",
        target,
        m.pointCount(),
        m.lines().size(),
        m.objects().size() - 1,
        seconds);
    out.flush();
    return 0;
  }

  private static Path defaultOutput(Path log) {
    String name = log.getFileName().toString();
    int dot = name.lastIndexOf('.');
    String base = dot > 0 ? name.substring(0, dot) : name;
    Path parent = log.getParent();
    Path file = Path.of(base + ".map");
    return parent == null ? file : parent.resolve(file);
  }
}
