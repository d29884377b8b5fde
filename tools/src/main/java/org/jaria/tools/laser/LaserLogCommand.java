package org.jaria.tools.laser;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.jaria.action.ArActionGroupWander;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import org.jaria.laser.ArLaserLogger;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.tools.sim.SeededDrive;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria laser log}: wanders a robot with a laser and writes a scan log ({@code .2d}) as
 * sickLogger does, for {@code jaria map build}. On an embedded simulator ({@code --sim MAP}, in
 * virtual time, as fast as the computer goes) or on a robot or simulator at an address ({@code
 * --remote}, in real time).
 */
@Command(
    name = "log",
    description = {
      "Wander a robot with a laser and log its scans (.2d, ARIA's sickLogger format) for"
          + " 'jaria map build'.",
      "Examples:",
      "  jaria laser log --sim lab.map --seconds 600 --goal-every 60 -o lab.2d",
      "  jaria laser log --remote localhost:8101 --seconds 300 -o lab.2d   (jaria sim, MobileSim)"
    })
public final class LaserLogCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--sim",
      paramLabel = "MAP",
      description =
          "Log on an embedded simulator of this map (a .map file, or office, hall, columbia), in"
              + " virtual time.")
  String sim;

  @Option(
      names = "--remote",
      paramLabel = "ADDRESS",
      description =
          "Log on the robot or simulator at HOST:PORT (jaria sim, MobileSim) or a serial port, in"
              + " real time; its laser is the simulator's.")
  String remote;

  @Option(
      names = {"-o", "--output"},
      paramLabel = "FILE",
      description = "The log to write (default: ${DEFAULT-VALUE}, as sickLogger).")
  Path output = Path.of("1scans.2d");

  @Option(
      names = "--seconds",
      paramLabel = "S",
      description = "How long to wander (default: ${DEFAULT-VALUE}).")
  double seconds = 300;

  @Option(
      names = "--goal-every",
      paramLabel = "S",
      description = "Place a goal (goal1, goal2, ...) every S seconds (default: none).")
  double goalEvery;

  @Option(
      names = "--dist",
      paramLabel = "MM",
      description = "Log a scan every MM of travel (default: ${DEFAULT-VALUE}, as sickLogger).")
  double dist = 300;

  @Option(
      names = "--deg",
      paramLabel = "DEG",
      description = "Or every DEG of turning, whichever comes first (default: ${DEFAULT-VALUE}).")
  double deg = 25;

  @Option(
      names = "--odometry-error",
      paramLabel = "SPEC",
      description =
          "With --sim: none, constant:T,R or random:T,R (default: ${DEFAULT-VALUE}, as a real"
              + " robot drifts).")
  String odometryError = "random:0.02,0.02";

  @Option(names = "--seed", description = "With --sim: random seed (default: ${DEFAULT-VALUE}).")
  long seed = 1;

  @Override
  public Integer call() throws InterruptedException {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if ((sim == null) == (remote == null)) {
      err.println(
          "give --sim MAP (an embedded simulator) or --remote HOST:PORT (a robot or simulator)");
      return 2;
    }
    if (!(seconds > 0) || goalEvery < 0 || !(dist > 0) || !(deg > 0)) {
      err.println("--seconds, --dist and --deg must be positive, --goal-every not negative");
      return 2;
    }
    try {
      return sim != null ? onSimulator(out, err) : onRobot(out, err);
    } catch (IllegalArgumentException | IOException | MapFormatException e) {
      err.println(e.getMessage());
      return 1;
    }
  }

  private int onSimulator(PrintWriter out, PrintWriter err) throws IOException, MapFormatException {
    SimulatedRobot s = SeededDrive.p3dx(ArMap.load(sim), seed, odometryError);
    try {
      ArRobot robot = s.robot();
      ArSimulatedLaser laser = prepare(robot);
      s.runMillis(1000);
      ArLaserLogger logger = open(robot, laser, err);
      if (logger == null) {
        return 1;
      }
      wander(robot);
      out.printf(Locale.ROOT, "logging %s on %s for %.0f s (simulated)%n", output, sim, seconds);
      out.flush();
      long step = 1000;
      long total = (long) (seconds * 1000);
      for (long t = 0; t < total; t += step) {
        s.runMillis(Math.min(step, total - t));
        placeGoal(logger, t, step);
      }
      robot.stop();
      s.runMillis(500);
      return finish(logger, robot, out, err);
    } finally {
      s.close();
      s.world().close();
    }
  }

  private int onRobot(PrintWriter out, PrintWriter err) throws InterruptedException {
    ArRobot robot = new ArRobot();
    robot.setDeviceConnection(RobotAddress.parse(remote).connection(Clock.system()));
    if (!robot.blockingConnect()) {
      err.println("could not connect to " + remote + ": " + robot.getConnectFailure());
      return 1;
    }
    try {
      robot.runAsync(true);
      ArSimulatedLaser laser = prepare(robot);
      TimeUnit.MILLISECONDS.sleep(1000); // the laser's first sweeps (the log's header needs one)
      ArLaserLogger logger = open(robot, laser, err);
      if (logger == null) {
        return 1;
      }
      wander(robot);
      out.printf(Locale.ROOT, "logging %s on %s for %.0f s%n", output, remote, seconds);
      out.flush();
      long step = 1000;
      long total = (long) (seconds * 1000);
      for (long t = 0; t < total && robot.isConnected(); t += step) {
        TimeUnit.MILLISECONDS.sleep(step);
        placeGoal(logger, t, step);
      }
      robot.stop();
      return finish(logger, robot, out, err);
    } finally {
      robot.stopRunning();
      robot.disconnect();
    }
  }

  /** The simulator's laser, and sonar for avoiding obstacles. */
  private static ArSimulatedLaser prepare(ArRobot robot) {
    ArSimulatedLaser laser = new ArSimulatedLaser();
    robot.lock();
    try {
      robot.addRangeDevice(laser);
      robot.addRangeDevice(new ArSonarDevice());
    } finally {
      robot.unlock();
    }
    return laser;
  }

  /**
   * ARIA's wander group, motors on: once the logger is open, so the log starts where the robot
   * starts (the map's home).
   */
  private static void wander(ArRobot robot) {
    robot.lock();
    try {
      new ArActionGroupWander(robot).activateExclusive();
      robot.enableMotors();
    } finally {
      robot.unlock();
    }
  }

  private ArLaserLogger open(ArRobot robot, ArSimulatedLaser laser, PrintWriter err) {
    ArLaserLogger logger = new ArLaserLogger(robot, laser, dist, deg, output.toString());
    if (!logger.wasFileOpenedSuccessfully()) {
      err.println(logger.getFailure());
      logger.close();
      return null;
    }
    return logger;
  }

  private void placeGoal(ArLaserLogger logger, long t, long step) {
    if (goalEvery > 0) {
      long every = (long) (goalEvery * 1000);
      if ((t + step) / every > t / every) {
        logger.addGoal();
      }
    }
  }

  private static int finish(ArLaserLogger logger, ArRobot robot, PrintWriter out, PrintWriter err) {
    logger.close();
    if (!logger.getFailure().isEmpty()) {
      err.println(logger.getFailure());
      return 1;
    }
    out.printf(
        Locale.ROOT,
        "wrote %s: %d scans over %.0f m; build it with: jaria map build %s%n",
        logger.getFileName(),
        logger.getScanCount(),
        robot.getOdometerDistance() / 1000,
        logger.getFileName());
    out.flush();
    return 0;
  }
}
