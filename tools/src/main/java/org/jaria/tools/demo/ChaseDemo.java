package org.jaria.tools.demo;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.server.ActsServer;
import org.jaria.acts.server.ServerSettings;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.clock.Clock;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.jaria.simvision.ChaseScene;
import org.jaria.simvision.SimCameraPtz;
import org.jaria.simvision.SimCameraSource;
import org.jaria.tools.examples.ActsColorFollowingExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria demo chase}: the thesis's vision-control application on the simulator. A red ball
 * rolls slowly back and forth in the hall; the simulated camera's pictures go to a real ACTS server
 * (TCP) with channel 1 trained on the ball; the program connects to the simulator and to ACTS as it
 * would on the robot, and chases the ball.
 */
@Command(name = "chase", description = "Vision control (thesis §6.4): chase a red ball with ACTS.")
final class ChaseDemo extends DemoOptions implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--ball-speed",
      description = "How fast the ball rolls, mm/s (default: ${DEFAULT-VALUE}).",
      defaultValue = "150")
  double ballSpeed = 150;

  @Option(
      names = "--keys",
      description = "Read keys from this terminal: 'a' toggles keyboard driving, arrows drive.")
  boolean keys;

  ChaseDemo() {
    map = "hall";
  }

  @Override
  public Integer call() throws Exception {
    PrintWriter out = spec.commandLine().getOut();
    try (EmbeddedSimulator sim = new EmbeddedSimulator(map, model, seed)) {
      ChaseScene scene = new ChaseScene(sim.world, sim.robot, 2500, 300);
      double x0 = scene.ball().x();
      double y0 = scene.ball().y();
      long t0 = sim.world.getClock().nanoTime();
      double amplitude = 1500;
      double period = 4 * amplitude / Math.max(1, ballSpeed);
      sim.world.addStepListener(
          () -> {
            double t = (sim.world.getClock().nanoTime() - t0) / 1e9;
            double s = amplitude * Math.sin(2 * Math.PI * t / period);
            scene.moveBall(x0, y0 + s);
          });
      VisionPipeline pipeline =
          new VisionPipeline(
              new SimCameraSource(scene.camera), scene.bank, TrackerSettings.DEFAULT);
      try (ActsServer acts =
              new ActsServer(
                  pipeline, ServerSettings.DEFAULT.withAddress("127.0.0.1", 0), Clock.system());
          DemoTicker ticker = new DemoTicker("demo-status", seconds);
          ArKeyHandler keyHandler = keys ? ArKeyHandler.forTerminal() : new ArKeyHandler()) {
        acts.start();
        out.printf(
            Locale.ROOT,
            "Simulator on tcp port %d, ACTS on tcp port %d, channel 1 trained on the red ball.%n",
            sim.port(),
            acts.getPort());
        out.flush();
        String[] args = {
          "-rh",
          "127.0.0.1",
          "-rrtp",
          String.valueOf(sim.port()),
          "-actsPort",
          String.valueOf(acts.getPort())
        };
        return ActsColorFollowingExample.run(
            args,
            new SimCameraPtz(scene.camera),
            keyHandler,
            robot -> watch(ticker, robot, scene, out),
            running(keys));
      }
    }
  }

  /** What the demo says once the program runs: channel 1 is trained, and whether keys are read. */
  static String running(boolean keys) {
    return "Running: the robot drives towards the red ball that ACTS sees on channel 1 (trained on"
        + " it already)."
        + (keys
            ? " Press 'a' to switch to keyboard driving (the arrows drive), 'a' again to chase."
            : " The keyboard is not read; with --keys, 'a' switches to keyboard driving.");
  }

  private static void watch(DemoTicker ticker, ArRobot robot, ChaseScene scene, PrintWriter out) {
    ticker.start(
        robot,
        s -> {
          out.printf(
              Locale.ROOT,
              "t=%3ds  robot %-26s vel %4.0f mm/s  ball %.0f mm away%n",
              s,
              scene.robot.getTruePose(),
              robot.getVel(),
              scene.distanceToBall());
          out.flush();
        });
  }
}
