package org.jaria.tools.demo;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.jaria.tools.desktop.Desktop;
import org.jaria.tools.examples.GotoActionExample;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria demo}: the thesis's applications, each against an embedded simulator unless a robot
 * address is given. Without a subcommand it runs {@code wander}.
 */
@Command(
    name = "demo",
    description = {
      "Run one of the thesis's applications (default: wander) on an embedded simulator.",
      "With --remote they drive that robot or simulator instead."
    },
    subcommands = {
      DemoCommand.Wander.class,
      GyroDemo.class,
      GotoDemo.class,
      ChaseDemo.class,
      NavigateDemoCommand.class,
      org.jaria.tools.guiserver.GuiServerCommand.class
    })
public final class DemoCommand extends DemoOptions implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--gui",
      description =
          "Watch it in the simulator view (needs a display); closing the window ends the demo.")
  boolean gui;

  @picocli.CommandLine.Mixin
  org.jaria.tools.web.WebOption web = new org.jaria.tools.web.WebOption();

  /** Without a subcommand: wander, with the options given to {@code demo}. */
  @Override
  public Integer call() throws Exception {
    Wander w = new Wander();
    w.spec = spec;
    w.map = map;
    w.model = model;
    w.seconds = seconds;
    w.seed = seed;
    w.remote = remote;
    w.gui = gui;
    w.web = web;
    return w.call();
  }

  /** {@code jaria demo wander}: obstacle avoidance (gotoActionExample). */
  @Command(
      name = "wander",
      description =
          "Obstacle avoidance (thesis §6.3): wander with five actions past crates put in the"
              + " robot's way, printing progress and every turn away from something.")
  static final class Wander extends DemoOptions implements Callable<Integer> {

    @Spec CommandSpec spec;

    @Option(
        names = "--gui",
        description =
            "Watch it in the simulator view (needs a display); closing the window ends the demo.")
    boolean gui;

    @Option(
        names = "--laser",
        paramLabel = "lms2xx|urg",
        description =
            "Also avoid with a laser: the simulator's, presented as a real LMS-200 or URG on a"
                + " loopback port, or with --remote the one on --laser-port.")
    String laser;

    @Option(names = "--laser-port", description = "The laser's serial device with --remote.")
    String laserPort;

    @picocli.CommandLine.Mixin
    org.jaria.tools.web.WebOption web = new org.jaria.tools.web.WebOption();

    @Override
    @SuppressWarnings("try") // the web view only needs closing
    public Integer call() throws Exception {
      PrintWriter out = spec.commandLine().getOut();
      PrintWriter err = spec.commandLine().getErr();
      if (gui && remote != null) {
        err.println(
            "jaria demo: --gui shows the embedded simulator; it cannot show a --remote robot");
        return 2;
      }
      if (gui) {
        Optional<String> problem = Desktop.problem();
        if (problem.isPresent()) {
          err.println("jaria demo: --gui: " + problem.get());
          return 1;
        }
      }
      if (web.enabled() && remote != null) {
        err.println(
            "jaria demo: --web shows the embedded simulator; it cannot show a --remote robot");
        return 2;
      }
      if (remote != null) {
        checkRemote();
        try (DemoTicker ticker = new DemoTicker("demo-status", seconds);
            DemoLaser l = laser == null ? null : new DemoLaser(laser, laserPort, null)) {
          out.println(stopsAfter(seconds));
          out.flush();
          return remoteFailed(
              GotoActionExample.run(
                  remoteArgs(), robot -> watch(ticker, robot, null, l, out), programErr()));
        }
      }
      try (EmbeddedSimulator sim = new EmbeddedSimulator(map, model, seed);
          DemoTicker ticker = new DemoTicker("demo-status", seconds);
          DemoLaser l = laser == null ? null : new DemoLaser(laser, null, sim)) {
        ArPose start = sim.robot.getTruePose();
        List<ObstaclesAhead.Crate> crates = ObstaclesAhead.place(sim.world, start);
        out.printf(
            Locale.ROOT,
            "Simulator: %s map, a %s on tcp port %d (real time); %d crates put in its way.%n",
            map,
            model,
            sim.port(),
            crates.size());
        out.printf(
            Locale.ROOT,
            "'pose' is where the robot believes it is (odometry, counted from (0, 0) where it"
                + " started); 'true' is where the simulator has it on the map, starting at"
                + " (%.0f, %.0f).%n",
            start.x(),
            start.y());
        out.println(stopsAfter(seconds));
        out.flush();
        var control = new org.jaria.web.source.SimulationControl(sim.world, 1.0);
        var source =
            new org.jaria.web.source.SimWorldSource(
                sim.world, control, org.jaria.tools.web.WebOption.mapOrNull(map), map);
        try (var view =
            web.start(
                "jaria demo · " + map,
                source,
                new org.jaria.web.control.Controls(null, control),
                out)) {
          if (!gui) {
            return runWander(sim, ticker, l, out);
          }
          return runWithWindow(sim, ticker, l, out, err);
        }
      }
    }

    private int runWander(EmbeddedSimulator sim, DemoTicker ticker, DemoLaser l, PrintWriter out) {
      int status =
          GotoActionExample.run(sim.connectArgs(), robot -> watch(ticker, robot, sim, l, out));
      ArPose truth = sim.robot.getTruePose();
      out.printf(Locale.ROOT, "Finished; the simulator's true pose of the robot is %s.%n", truth);
      out.flush();
      return status;
    }

    /** The program on a thread of its own while this one shows the window until it closes. */
    private int runWithWindow(
        EmbeddedSimulator sim, DemoTicker ticker, DemoLaser l, PrintWriter out, PrintWriter err)
        throws InterruptedException {
      AtomicReference<ArRobot> running = new AtomicReference<>();
      AtomicInteger status = new AtomicInteger();
      Thread program =
          new Thread(
              () -> {
                status.set(
                    GotoActionExample.run(
                        sim.connectArgs(),
                        robot -> {
                          running.set(robot);
                          watch(ticker, robot, sim, l, out);
                        }));
                // The demo's time is up (or the robot stopped): the window goes with it.
                Desktop.closeWindows();
              },
              "demo-program");
      program.start();
      out.println("Closing the window ends the demo sooner.");
      out.flush();
      int ui = Desktop.showUntilClosed("jaria demo --gui", sim.world, 1.0, err);
      ArRobot robot = running.get();
      if (robot != null) {
        robot.stopRunning();
      }
      program.join(TimeUnit.SECONDS.toMillis(10));
      return ui != 0 ? ui : status.get();
    }

    /**
     * Prints a status line every second, and a line whenever the robot turns away from something.
     */
    void watch(
        DemoTicker ticker, ArRobot robot, EmbeddedSimulator sim, DemoLaser l, PrintWriter out) {
      if (l != null) {
        l.attach(robot, out);
      }
      TurnReporter turns = new TurnReporter();
      long startNanos = robot.getClock().nanoTime();
      robot.addUserTask(
          "demo turn report",
          40,
          () -> {
            String line =
                turns.update(
                    (robot.getClock().nanoTime() - startNanos) / 1e9,
                    robot.getRotVel(),
                    robot.getClosestSonarRange(0, 90),
                    robot.getClosestSonarRange(-90, 0));
            if (line != null) {
              out.println(line);
              out.flush();
            }
          });
      ticker.start(
          robot,
          second -> {
            out.println(
                statusLine(second, robot, sim)
                    + (l == null ? "" : "  front laser " + l.closest(-45, 45) + "mm"));
            out.flush();
          });
    }
  }

  /** The honest closing time of a demo. */
  static String stopsAfter(int seconds) {
    return seconds == 0
        ? "Runs until Ctrl-C."
        : "Stops by itself after "
            + seconds
            + " s (--seconds N to change, 0 for no limit); Ctrl-C stops it sooner.";
  }

  static String statusLine(int second, ArRobot robot, EmbeddedSimulator sim) {
    int front = robot.getClosestSonarRange(-45, 45);
    StringBuilder sb =
        new StringBuilder(
            String.format(
                Locale.ROOT,
                "t=%3ds  pose %-26s vel %4.0f mm/s  rot %4.0f deg/s  front sonar %5s  driven %6.1f m",
                second,
                robot.getPose(),
                robot.getVel(),
                robot.getRotVel(),
                front < 0 ? "-" : front + "mm",
                robot.getOdometerDistance() / 1000));
    if (robot.isLeftMotorStalled() || robot.isRightMotorStalled()) {
      sb.append("  STALLED");
    }
    if (sim != null) {
      sb.append("  true ").append(sim.robot.getTruePose());
    }
    return sb.toString();
  }
}
