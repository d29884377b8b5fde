package org.jaria.tools.demo;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
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
    return w.call();
  }

  /** {@code jaria demo wander}: obstacle avoidance (gotoActionExample). */
  @Command(
      name = "wander",
      description =
          "Obstacle avoidance (thesis §6.3): wander with five actions, printing progress.")
  static final class Wander extends DemoOptions implements Callable<Integer> {

    @Spec CommandSpec spec;

    @Option(
        names = "--laser",
        paramLabel = "lms2xx|urg",
        description =
            "Also avoid with a laser: the simulator's, presented as a real LMS-200 or URG on a"
                + " loopback port, or with --remote the one on --laser-port.")
    String laser;

    @Option(names = "--laser-port", description = "The laser's serial device with --remote.")
    String laserPort;

    @Override
    public Integer call() throws Exception {
      PrintWriter out = spec.commandLine().getOut();
      if (remote != null) {
        try (DemoTicker ticker = new DemoTicker("demo-status", seconds);
            DemoLaser l = laser == null ? null : new DemoLaser(laser, laserPort, null)) {
          return GotoActionExample.run(remoteArgs(), robot -> watch(ticker, robot, null, l, out));
        }
      }
      try (EmbeddedSimulator sim = new EmbeddedSimulator(map, model, seed);
          DemoTicker ticker = new DemoTicker("demo-status", seconds);
          DemoLaser l = laser == null ? null : new DemoLaser(laser, null, sim)) {
        out.printf(
            Locale.ROOT,
            "Simulator: %s map, a %s on tcp port %d (real time).%n",
            map,
            model,
            sim.port());
        out.flush();
        int status =
            GotoActionExample.run(sim.connectArgs(), robot -> watch(ticker, robot, sim, l, out));
        ArPose truth = sim.robot.getTruePose();
        out.printf(Locale.ROOT, "Finished; the simulator's true pose of the robot is %s.%n", truth);
        out.flush();
        return status;
      }
    }

    /** Prints a status line every second and stops the robot after the time limit. */
    void watch(
        DemoTicker ticker, ArRobot robot, EmbeddedSimulator sim, DemoLaser l, PrintWriter out) {
      if (l != null) {
        l.attach(robot, out);
      }
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
