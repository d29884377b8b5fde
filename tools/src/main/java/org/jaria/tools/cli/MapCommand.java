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
import org.jaria.map.MapNames;
import org.jaria.sim.MapBudget;
import org.jaria.sim.MapSupport;
import org.jaria.sim.world.MapCost;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jaria map info FILE}: what a map file holds, what it costs the simulator (a map over the
 * simulator's {@link MapBudget} is refused as {@code jaria sim -m} refuses it), and whether it
 * reads and writes back cleanly.
 */
@Command(
    name = "map",
    description =
        "Inspect ArMap .map files, or build one from a laser scan log (the map editor is 'jaria"
            + " mapper').",
    subcommands = {MapCommand.Info.class, MapBuildCommand.class, MapSketchCommand.class})
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

    @Parameters(
        paramLabel = "MAP",
        description = "A .map file, or a bundled map: office, hall, columbia.")
    String map;

    @Override
    public Integer call() throws IOException, MapFormatException {
      PrintWriter out = spec.commandLine().getOut();
      boolean bundled = MapNames.bundledName(map) != null;
      ArMap m = ArMap.load(map); // what goes wrong is said once, by the command line
      MapCost cost = MapSupport.cost(m);
      String over = MapBudget.DEFAULT.overBy(cost);
      if (over != null) {
        // the same refusal, in the same words, as 'jaria sim -m' and a client's map load
        throw new IOException("map " + map + " is too big for the simulator: " + over);
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
      out.printf(
          Locale.ROOT,
          "  cost     %,d grid cells in the simulator's index at most (it takes %,d)%n",
          cost.cellEntries(),
          MapBudget.DEFAULT.maxCellEntries());
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
