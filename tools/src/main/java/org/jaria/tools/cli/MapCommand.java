package org.jaria.tools.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jaria map info FILE}: what a map file holds, and whether it reads and writes back cleanly.
 */
@Command(
    name = "map",
    description =
        "Inspect ArMap .map files, or build one from a laser scan log (the map editor is 'jaria"
            + " mapper').",
    subcommands = {MapCommand.Info.class, MapBuildCommand.class})
final class MapCommand implements Runnable {

  @Spec CommandSpec spec;

  @Override
  public void run() {
    spec.commandLine().usage(spec.commandLine().getOut());
  }

  /** {@code jaria map info FILE|NAME}. */
  @Command(
      name = "info",
      description = "Print a map's size, lines, points and objects, and check it round-trips.")
  static final class Info implements Callable<Integer> {

    @Spec CommandSpec spec;

    @Parameters(paramLabel = "MAP", description = "A .map file, or a bundled map: office, hall.")
    String map;

    @Override
    public Integer call() throws IOException {
      PrintWriter out = spec.commandLine().getOut();
      ArMap m;
      boolean bundled = ArMap.BUNDLED_MAPS.contains(map);
      try {
        m = ArMap.load(map);
      } catch (MapFormatException e) {
        spec.commandLine().getErr().println(e.getMessage());
        return 1;
      }
      out.printf(Locale.ROOT, "%s (%s)%n", map, m.getMapType());
      out.printf(
          Locale.ROOT,
          "  extent   %s .. %s%n  lines    %d%n  points   %d%n  objects  %d (%d goals)%n",
          m.getMinPos(),
          m.getMaxPos(),
          m.getLines().size(),
          m.getPoints().size(),
          m.getMapObjects().size(),
          m.getGoals().size());
      m.findHomePose().ifPresent(h -> out.println("  home     " + h));
      for (ArMapObject o : m.getMapObjects()) {
        out.printf(Locale.ROOT, "  %-16s %-24s %s%n", o.type(), '"' + o.name() + '"', o.pose());
      }
      for (String w : m.getWarnings()) {
        out.println("  warning  " + w);
      }
      StringWriter rewritten = new StringWriter();
      m.write(rewritten);
      boolean reloadsEqual;
      try {
        reloadsEqual =
            m.equals(ArMap.read(new java.io.StringReader(rewritten.toString()), "rewritten"));
      } catch (MapFormatException e) {
        reloadsEqual = false;
      }
      out.println(reloadsEqual ? "  reloads equal after writing" : "  DOES NOT reload equal");
      if (!bundled) {
        String original = Files.readString(Path.of(map), StandardCharsets.ISO_8859_1);
        out.println(
            original.equals(rewritten.toString())
                ? "  writes back byte for byte"
                : "  writes back with layout differences");
      }
      out.flush();
      return 0;
    }
  }
}
