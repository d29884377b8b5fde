package org.jaria.tools.sim;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.jaria.sim.SimWorld;
import org.jaria.tools.desktop.Desktop;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria sim [--gui] ...}: the simulator command with a window. Every option of {@link
 * SimCommand} works as before; with {@code --gui} the world is also drawn live in the simulator
 * view (the robots still listen on TCP), and closing the window ends the simulator.
 *
 * <p>Register this class instead of {@link SimCommand} to give {@code jaria sim} its {@code --gui}
 * option.
 */
@Command(
    name = "sim",
    description = {
      "Runs a simulated world with ARCOS robots on TCP ports 8101, 8102, ... (a MobileSim analogue).",
      "Connect any ARIA client (e.g. -remoteHost localhost -remoteRobotTcpPort 8101). Ctrl-C stops;"
          + " with --gui, closing the window stops."
    })
public final class SimGuiCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Mixin SimCommand sim = new SimCommand();

  @Option(names = "--gui", description = "Show the world in a window (the simulator view).")
  boolean gui;

  @Override
  public Integer call() throws Exception {
    if (!gui) {
      return sim.call();
    }
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    sim.noteDeprecatedOptions(err);
    Optional<String> problem = Desktop.problem();
    if (problem.isPresent()) {
      err.println("sim: --gui: " + problem.get());
      return 1;
    }
    SimWorld world;
    try {
      world = openAndAnnounce(out);
    } catch (IOException e) {
      err.println("sim: " + e.getMessage());
      return 1;
    }
    try {
      out.println("close the window to stop the simulator");
      out.flush();
      return Desktop.showUntilClosed("jaria sim --gui", world, speedup(), err);
    } finally {
      world.close();
    }
  }

  /**
   * Builds the world the options describe, opens its ports and says on {@code out} where each robot
   * factory and robot listens, one line each as {@code jaria sim} without a window does.
   *
   * @throws IOException if the map cannot be read or a port is in use (the world is then closed)
   */
  SimWorld openAndAnnounce(PrintWriter out) throws IOException {
    SimWorld world = sim.createWorld();
    try {
      world.listen();
    } catch (IOException e) {
      world.close();
      throw e;
    }
    SimCommand.printListening(world, out);
    out.flush();
    return world;
  }

  /** The pacing the options ask for: 0 for --unthrottled, else --speedup (default 1). */
  double speedup() {
    return sim.pacing();
  }
}
