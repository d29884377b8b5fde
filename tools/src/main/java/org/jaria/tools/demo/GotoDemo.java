package org.jaria.tools.demo;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.tools.examples.GotoExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code jaria demo goto}: drive a square of goals with ArActionGoto, avoiding obstacles. */
@Command(name = "goto", description = "Go to a list of poses (a 1.5 m square) avoiding obstacles.")
final class GotoDemo extends DemoOptions implements Callable<Integer> {

  @Spec CommandSpec spec;

  GotoDemo() {
    map = "hall";
  }

  @Override
  public Integer call() throws IOException {
    PrintStream out =
        new PrintStream(
            new java.io.FileOutputStream(java.io.FileDescriptor.out),
            true,
            StandardCharsets.UTF_8.name());
    try (EmbeddedSimulator sim = new EmbeddedSimulator(map, model, seed)) {
      out.printf(Locale.ROOT, "Simulator: %s map, a %s on tcp port %d.%n", map, model, sim.port());
      String[] args = remote != null ? remoteArgs() : sim.connectArgs();
      return GotoExample.run(args, GotoExample.SQUARE, out, robot -> {});
    }
  }
}
