package org.jaria.tools.demo;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.tools.examples.GyroExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria demo gyro}: the thesis's turn-control program on a simulated robot with a gyro. With
 * {@code --keys} the terminal's keys drive it; otherwise it presses s, d, f, a (turn to 90, 180,
 * 270, 0 degrees) every four seconds by itself.
 */
@Command(name = "gyro", description = "Turn control (thesis §6.2): gyro, wheel and fused headings.")
final class GyroDemo extends DemoOptions implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(names = "--keys", description = "Read keys from this terminal instead of a script.")
  boolean keys;

  /** What the demo says without --keys, where it presses the keys itself. */
  static final String SCRIPTED =
      "The demo presses the keys itself: s, d, f, a (turn to 90, 180, 270 and 0 degrees) at 4, 8,"
          + " 12 and 16 s.\nWith --keys you press them: arrows drive, space stops, 1-0 and q-p"
          + " turn, a/s/d/f turn to 0/90/180/270 degrees.";

  @Override
  public Integer call() throws IOException {
    PrintWriter writer = spec.commandLine().getOut();
    PrintStream out =
        new PrintStream(new WriterOutputStream(writer), true, StandardCharsets.UTF_8.name());
    try (EmbeddedSimulator sim =
            new EmbeddedSimulator(map, RobotOptions.of(model).withGyro(true), seed);
        ArKeyHandler keyHandler = keys ? ArKeyHandler.forTerminal() : new ArKeyHandler();
        DemoTicker ticker = new DemoTicker("demo-keys", seconds)) {
      out.printf(Locale.ROOT, "Simulator: a %s with a gyro on tcp port %d.%n", model, sim.port());
      return GyroExample.run(
          sim.connectArgs(),
          keyHandler,
          out,
          10,
          r -> script(ticker, r, keyHandler),
          keys ? GyroExample.KEYS : SCRIPTED);
    }
  }

  /** Without --keys, presses s, d, f, a at 4, 8, 12 and 16 seconds. */
  private void script(DemoTicker ticker, ArRobot robot, ArKeyHandler keyHandler) {
    String presses = keys ? "" : "sdfa";
    ticker.start(
        robot,
        s -> {
          int k = s / 4 - 1;
          if (s % 4 == 0 && k >= 0 && k < presses.length()) {
            keyHandler.feedKey(presses.charAt(k));
          }
        });
  }
}
