package org.jaria.tools.examples;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArPathPlanningTask.PathPlanningState;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.connection.RobotAddress;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.robot.ArRobot;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;

/**
 * The thesis's path-following application (§6.1): connect, localize at home, plan to each goal in
 * turn and drive there, reporting progress and the final error. With no robot address it runs on an
 * embedded simulator (p3dx-sh, odometry error on), either in lockstep as fast as the computer goes
 * ({@code speedUp} 0) or paced to the wall clock ({@code speedUp} > 0); with an address ({@code
 * host:port}) it drives that robot (a real one or an external simulator) with the localization and
 * planning threads of a real deployment.
 *
 * <p>Headless; prints to the given stream. {@link #run(Options, PrintStream)} returns the outcome
 * of every goal; {@link #main} exits 0 if every goal was reached.
 */
public final class NavigateDemo {

  private NavigateDemo() {}

  /**
   * What to run.
   *
   * @param map a map file, or a bundled map name ("office", "hall")
   * @param goals goal names from the map (or poses written "x,y" / "x,y,th"), visited in order
   * @param robotAddress the robot to drive ({@link RobotAddress}: host[:port] or a serial device),
   *     or null for the embedded simulator
   * @param speedUp for the embedded simulator: 0 = lockstep, as fast as possible; otherwise
   *     simulated seconds per real second
   * @param seed seed of the simulator and the localization
   * @param goalTimeout how long to wait for one goal
   * @param world for the embedded simulator: the world the robot drives in, if not {@code map} (a
   *     map built from a scan log of that world: the robot starts at the world's home, which is the
   *     built map's RobotHome, and localizes and plans on the built map), or null
   */
  public record Options(
      String map,
      List<String> goals,
      String robotAddress,
      double speedUp,
      long seed,
      Duration goalTimeout,
      String world) {

    /** Options whose world is the map itself. */
    public Options(
        String map,
        List<String> goals,
        String robotAddress,
        double speedUp,
        long seed,
        Duration goalTimeout) {
      this(map, goals, robotAddress, speedUp, seed, goalTimeout, null);
    }

    /** Checks and copies. */
    public Options {
      Objects.requireNonNull(
          map, "a map is needed: a .map file or a bundled name (office, hall, columbia)");
      goals = List.copyOf(goals);
      if (goals.isEmpty()) {
        throw new IllegalArgumentException("give at least one goal (a goal name from the map)");
      }
      if (!(speedUp >= 0)) {
        throw new IllegalArgumentException("speed-up must be 0 (lockstep) or positive");
      }
    }

    /** Defaults: embedded lockstep simulator, seed 1, 10 minutes per goal. */
    public static Options of(String map, List<String> goals) {
      return new Options(map, goals, null, 0, 1, Duration.ofMinutes(10));
    }
  }

  /**
   * How one goal went.
   *
   * @param goal the goal as given
   * @param state the final state
   * @param status the task's status text
   * @param seconds time spent on the goal, s
   * @param goalError distance from where the robot really stopped to the goal, mm (from the
   *     simulator's true pose; on a real robot from the localized pose); NaN if not reached
   * @param locError localization error at the end (simulator only; NaN otherwise), mm
   * @param locErrorDeg heading error of the localization at the end, degrees (NaN if unknown)
   */
  public record GoalOutcome(
      String goal,
      PathPlanningState state,
      String status,
      double seconds,
      double goalError,
      double locError,
      double locErrorDeg) {

    /** Whether the goal was reached. */
    public boolean reached() {
      return state == PathPlanningState.REACHED_GOAL;
    }
  }

  /**
   * The whole run.
   *
   * @param localized whether localization at home passed
   * @param outcomes one per goal, in order
   */
  public record Result(boolean localized, List<GoalOutcome> outcomes) {

    /** Copies. */
    public Result {
      outcomes = List.copyOf(outcomes);
    }

    /** 0 if every goal was reached, 1 otherwise. */
    public int exitCode() {
      return outcomes.stream().allMatch(GoalOutcome::reached) ? 0 : 1;
    }
  }

  /**
   * Runs the application (the form the {@code ./jaria demo navigate} command calls).
   *
   * @return 0 if every goal was reached, 1 if some was not, 2 if it could not start
   */
  public static int run(
      String map, List<String> goals, String robotAddress, PrintStream out, double speedUp) {
    return run(map, null, goals, robotAddress, out, speedUp);
  }

  /** As above, the embedded simulator's world being {@code world} (null: the map itself). */
  public static int run(
      String map,
      String world,
      List<String> goals,
      String robotAddress,
      PrintStream out,
      double speedUp) {
    try {
      return run(
              new Options(map, goals, robotAddress, speedUp, 1, Duration.ofMinutes(10), world), out)
          .exitCode();
    } catch (IllegalArgumentException | IllegalStateException | UncheckedIOException e) {
      out.println("navigate: " + e.getMessage());
      return 2;
    }
  }

  /** Runs the application. */
  public static Result run(Options o, PrintStream out) {
    ArMap map = loadMap(o.map());
    if (o.robotAddress() != null && !o.robotAddress().isBlank()) {
      return runOnRobot(o, map, out);
    }
    return runOnSimulator(o, map, out);
  }

  /** A map file, or a bundled map name. */
  public static ArMap loadMap(String mapOrName) {
    try {
      return ArMap.load(mapOrName);
    } catch (IOException e) {
      throw new UncheckedIOException(e.getMessage(), e); // says what is wrong and what to do
    } catch (MapFormatException e) {
      throw new IllegalArgumentException("not a valid map: " + e.getMessage(), e);
    }
  }

  private static Result runOnSimulator(Options o, ArMap map, PrintStream out) {
    SimOptions options =
        SimOptions.builder().seed(o.seed()).odometryError(OdometryError.random(0.02, 0.02)).build();
    ArMap worldMap = o.world() == null ? map : loadMap(o.world());
    try (SimWorld world = SimWorld.create(worldMap, options)) {
      SimRobot simRobot = world.addRobot("p3dx-sh");
      SimulatedRobot sim = SimulatedRobot.connect(world, simRobot);
      try {
        out.printf(
            Locale.ROOT,
            "Embedded simulator: %s on %s (%s)%n",
            simRobot.getName(),
            o.world() == null ? o.map() : o.world() + ", navigating on " + o.map(),
            o.speedUp() == 0 ? "lockstep" : "x" + o.speedUp() + " real time");
        Navigator nav =
            Navigator.create(
                sim.robot(),
                map,
                ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS,
                ArPathPlanningTask.PlanMode.SYNCHRONOUS,
                o.seed());
        Stepper stepper;
        if (o.speedUp() > 0) {
          world.startRealTime(o.speedUp());
          stepper = ms -> sleepReal(Math.max(1, (long) (ms / o.speedUp())));
        } else {
          stepper = sim::runMillis;
        }
        try {
          // in another world than the map, the true pose is in the world's frame: not compared
          return nav.visit(o, out, stepper, o.world() == null ? simRobot : null);
        } finally {
          world.stopRealTime();
          nav.close();
        }
      } finally {
        sim.close();
      }
    }
  }

  private static Result runOnRobot(Options o, ArMap map, PrintStream out) {
    RobotAddress address = RobotAddress.parse(o.robotAddress());
    ArRobot robot = new ArRobot("robot");
    try {
      robot.setDeviceConnection(address.open(robot.getClock(), "--remote"));
    } catch (IOException e) {
      throw new IllegalStateException(e.getMessage(), e);
    }
    if (!robot.blockingConnect()) {
      throw new IllegalStateException(
          "could not connect to the robot at " + address + ": " + robot.getConnectFailure());
    }
    robot.runAsync(true);
    try {
      out.println("Connected to " + robot.getRobotName() + " (" + robot.getRobotSubType() + ")");
      Navigator nav =
          Navigator.create(
              robot,
              map,
              ArSonarLocalizationTask.UpdateMode.THREADED,
              ArPathPlanningTask.PlanMode.THREADED,
              o.seed());
      try {
        return nav.visit(o, out, NavigateDemo::sleepReal, null);
      } finally {
        nav.close();
      }
    } finally {
      robot.close();
    }
  }

  /** Lets time pass: simulated (lockstep) or real. */
  @FunctionalInterface
  interface Stepper {
    void run(long millis);
  }

  private static void sleepReal(long ms) {
    try {
      Thread.sleep(ms);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted", e);
    }
  }

  static String fmt(ArPose p) {
    return String.format(Locale.ROOT, "(%.0f, %.0f, %.0f°)", p.x(), p.y(), p.th());
  }

  static double headingError(ArPose a, ArPose b) {
    return Math.abs(ArMath.subAngle(a.th(), b.th()));
  }

  /** Command line: {@code --map FILE --goal NAME [--goal NAME ...] [--robot host:port]}. */
  public static void main(String[] args) {
    String map = null;
    String robot = null;
    double speed = 0;
    List<String> goals = new ArrayList<>();
    int i = 0;
    while (i < args.length) {
      String a = args[i];
      String v = i + 1 < args.length ? args[i + 1] : null;
      switch (a) {
        case "--map" -> map = v;
        case "--goal" -> goals.add(v);
        case "--robot" -> robot = v;
        case "--speed" -> speed = v == null ? 0 : Double.parseDouble(v);
        default -> {
          System.out.println(
              "usage: NavigateDemo --map FILE|office|hall --goal NAME [--goal NAME ...]"
                  + " [--robot host:port] [--speed N]");
          System.exit(2);
        }
      }
      i += 2;
    }
    System.exit(run(map, goals, robot, System.out, speed));
  }
}
