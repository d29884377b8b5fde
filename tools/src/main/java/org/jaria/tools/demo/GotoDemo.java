package org.jaria.tools.demo;

import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.geom.ArPose;
import org.jaria.tools.examples.GotoExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jaria demo goto}: drive to a list of poses with ArActionGoto, avoiding obstacles. */
@Command(
    name = "goto",
    description =
        "Go to a list of poses (default: a 1.5 m square) with ArActionGoto, avoiding obstacles.")
final class GotoDemo extends DemoOptions implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--pose",
      paramLabel = "X,Y",
      description =
          "A goal in mm relative to where the robot starts (repeatable; default: the square).")
  List<String> poses = new ArrayList<>();

  GotoDemo() {
    map = "hall";
  }

  @Override
  public Integer call() throws Exception {
    PrintStream out =
        new PrintStream(
            new WriterOutputStream(spec.commandLine().getOut()), true, StandardCharsets.UTF_8);
    List<ArPose> goals = poses.isEmpty() ? GotoExample.SQUARE : parse(poses);
    if (remote != null) {
      checkRemote();
      return remoteFailed(GotoExample.run(remoteArgs(), goals, out, robot -> {}, programErr()));
    }
    try (EmbeddedSimulator sim = new EmbeddedSimulator(map, model, seed)) {
      out.printf(Locale.ROOT, "Simulator: %s map, a %s on tcp port %d.%n", map, model, sim.port());
      return GotoExample.run(sim.connectArgs(), goals, out, robot -> {});
    }
  }

  /** "x,y" pairs in mm. */
  private List<ArPose> parse(List<String> poses) {
    List<ArPose> l = new ArrayList<>();
    for (String p : poses) {
      String[] xy = p.split(",", -1);
      try {
        if (xy.length != 2) {
          throw new NumberFormatException();
        }
        l.add(new ArPose(Double.parseDouble(xy[0].trim()), Double.parseDouble(xy[1].trim())));
      } catch (NumberFormatException e) {
        throw new picocli.CommandLine.ParameterException(
            spec.commandLine(),
            "--pose wants X,Y in millimetres, e.g. --pose 1500,0; got '" + p + "'");
      }
    }
    return l;
  }
}
