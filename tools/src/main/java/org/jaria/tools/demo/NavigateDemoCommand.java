package org.jaria.tools.demo;

import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.jaria.tools.examples.NavigateDemo;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code jaria demo navigate}: the thesis's path-following application (§6.1). Localizes at home,
 * plans to each goal in turn and drives there, printing progress and the final error.
 */
@Command(
    name = "navigate",
    description = {
      "Path following (thesis §6.1): localize at home, plan and drive to each --goal in turn.",
      "Without --remote it runs an embedded simulator in lockstep (as fast as the computer goes)."
    })
final class NavigateDemoCommand implements Callable<Integer> {

  @Option(
      names = "--map",
      description =
          "Bundled map (office, hall, columbia) or .map file (default: ${DEFAULT-VALUE}).",
      defaultValue = "office")
  String map = "office";

  @Option(
      names = "--world",
      paramLabel = "FILE",
      description =
          "The embedded simulator's world, if not the map: e.g. the building a map was built in"
              + " with 'jaria laser log' and 'jaria map build' (the robot starts at its home).")
  String world;

  @Option(
      names = "--goal",
      paramLabel = "NAME",
      description = "A goal name from the map, or a pose x,y[,th] in mm/degrees (repeatable).")
  List<String> goals = new ArrayList<>();

  @Option(
      names = "--remote",
      paramLabel = "HOST[:PORT]|DEVICE",
      description =
          "Drive this robot or external simulator instead of an embedded one (a serial device"
              + " such as /dev/ttyS0 for a robot on a serial port).")
  String remote;

  @Option(
      names = "--speed",
      paramLabel = "X",
      description =
          "Embedded simulator pace: 0 = lockstep, as fast as possible (default), else x real time.")
  double speed;

  @Override
  public Integer call() {
    List<String> g = goals.isEmpty() ? List.of(defaultGoal(map)) : goals;
    PrintStream out = new PrintStream(System.out, true, StandardCharsets.UTF_8);
    return NavigateDemo.run(map, world, g, remote, out, speed);
  }

  /**
   * A goal that exists in the bundled maps, so {@code jaria demo navigate} works without options.
   */
  private static String defaultGoal(String map) {
    var mapGoals = NavigateDemo.loadMap(map).getGoals();
    return mapGoals.isEmpty() ? "0,0" : mapGoals.get(0).name();
  }
}
