package org.jaria.apps.simview;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppCommand;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppLauncher;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.map.MapNames;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria simview}: a simulated world in a window (what {@code jaria sim --gui} opens). The
 * robots listen on TCP ports 8101, 8102... like {@code jaria sim}, so ARIA clients can drive them
 * while you watch.
 */
@Command(
    name = "simview",
    mixinStandardHelpOptions = true,
    sortOptions = false,
    description = {
      "The simulator with a window: map, robots, sonar, laser, camera field of view, true pose"
          + " against odometry; run/pause, step and speed; place robots and move obstacles with"
          + " the mouse. Robots listen on TCP 8101, 8102... unless --no-listen."
    })
public final class SimViewCommand implements Callable<Integer>, AppCommand {

  @Spec CommandSpec spec;

  @Option(
      names = "--map",
      paramLabel = "FILE",
      description =
          "ArMap .map file, or a bundled map name (office, hall, columbia); default: office")
  String map = "office";

  @Option(names = "--robot", paramLabel = "MODEL", description = "Robot model to add (repeatable).")
  List<String> robots = new ArrayList<>();

  @Option(names = "--robots", paramLabel = "N", description = "Number of robots.")
  Integer robotCount;

  @Option(names = "--laser", description = "Give every robot a simulated laser.")
  boolean laser;

  @Option(names = "--seed", description = "Random seed (default ${DEFAULT-VALUE}).")
  long seed = 1;

  @Option(
      names = "--odometry-error",
      paramLabel = "SPEC",
      description = "Odometry error: none, constant:T,R or random:T,R (per metre, per radian).")
  String odometryError = "none";

  @Option(names = "--port", description = "TCP port of the first robot (default 8101).")
  int port = SimOptions.DEFAULT_PORT;

  @Option(names = "--no-listen", description = "Do not open TCP ports (view only).")
  boolean noListen;

  @Option(names = "--speedup", paramLabel = "X", description = "Speed (1 = real time; 0 = max).")
  double speedup = 1;

  @Option(names = "--paused", description = "Start paused (use Step or Run).")
  boolean paused;

  @Option(
      names = "--region",
      paramLabel = "X0,Y0,X1,Y1",
      description = "Show this part of the map (mm) instead of all of it.")
  String region;

  @Option(
      names = "--advance",
      paramLabel = "MS",
      description = "Simulate this many milliseconds before showing (e.g. for screenshots).")
  long advanceMillis;

  @Option(
      names = "--demo",
      description =
          "Connect a built-in client that wanders the first robot around with its sonar"
              + " (something to watch without an ARIA program).")
  boolean demo;

  @Override
  public String appName() {
    return "simview";
  }

  /**
   * Builds the world the options describe.
   *
   * @throws IOException if the map cannot be read (message names file and line)
   * @throws IllegalArgumentException if an option is wrong
   */
  public SimWorld createWorld() throws IOException {
    SimOptions options =
        SimOptions.builder()
            .seed(seed)
            .basePort(port)
            .odometryError(OdometryError.parse(odometryError))
            .build();
    String bundled = MapNames.bundledName(map);
    SimWorld world;
    if (bundled != null) {
      world = SimWorld.bundled(bundled, options);
    } else {
      Optional<String> problem = MapNames.problem(map);
      if (problem.isPresent()) {
        throw new IOException(problem.get());
      }
      world = SimWorld.load(Path.of(map), options);
    }
    List<String> models = new ArrayList<>(robots.isEmpty() ? List.of("p3dx-sh") : robots);
    if (robotCount != null) {
      if (robotCount < 1 || robotCount > 100) {
        world.close();
        throw new IllegalArgumentException("--robots must be 1..100, was " + robotCount);
      }
      while (models.size() < robotCount) {
        models.add(models.get(models.size() - 1));
      }
    }
    try {
      for (String m : models) {
        // The models MobileSim gives a laser carry one anyway; --laser adds one to the others.
        RobotOptions o = RobotOptions.of(m);
        world.addRobot(laser ? o.withLaser(true) : o);
      }
    } catch (RuntimeException e) {
      world.close();
      throw e;
    }
    return world;
  }

  @Override
  public DesktopApp open(Stage stage, AppEnvironment env) throws IOException {
    SimWorld world = createWorld();
    SimSnapshot start = world.snapshot();
    SimViewWindow w;
    SimulatedRobot client = null;
    try {
      if (demo) {
        client = DemoDriver.start(world, world.getRobot(0));
      }
      if (advanceMillis > 0) {
        world.advanceMillis(advanceMillis);
      }
      // A screenshot must not open ports (nor fail because another simulator holds them).
      if (!noListen && env.interactive()) {
        world.listen();
      }
      w = new SimViewWindow(stage, env, world, speedup, true);
    } catch (IOException | RuntimeException e) {
      if (client != null) {
        client.close();
      }
      world.close();
      throw e;
    }
    if (client != null) {
      w.closeWith(client);
    }
    w.setOdometryStart(start);
    w.show(paused);
    if (region != null) {
      double[] r = parseRegion(region);
      w.showRegion(r[0], r[1], r[2], r[3]);
    }
    return w;
  }

  static double[] parseRegion(String s) {
    String[] p = s.split(",", -1);
    if (p.length != 4) {
      throw new IllegalArgumentException("--region expects X0,Y0,X1,Y1 in mm, got '" + s + "'");
    }
    double[] r = new double[4];
    try {
      for (int i = 0; i < 4; i++) {
        r[i] = Double.parseDouble(p[i].trim());
      }
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException("--region expects four numbers, got '" + s + "'", e);
    }
    return r;
  }

  @Override
  public Integer call() {
    PrintWriter err = spec.commandLine().getErr();
    return AppLauncher.runUntilClosed(this, err);
  }

  /**
   * Shows an existing world in a window until the user closes it (for {@code jaria sim --gui}):
   * starts JavaFX, opens the view running at {@code speedup}, and returns when the window closes.
   * The world is not closed.
   *
   * @return 0, or 1 if the window could not open (reported on {@code err})
   */
  public static int showUntilClosed(SimWorld world, double speedup, PrintWriter err) {
    AppCommand c =
        new AppCommand() {
          @Override
          public String appName() {
            return "simview";
          }

          @Override
          public DesktopApp open(Stage stage, AppEnvironment env) {
            SimViewWindow w = new SimViewWindow(stage, env, world, speedup, false);
            w.show(false);
            return w;
          }
        };
    return AppLauncher.runUntilClosed(c, err);
  }

  /** Runs the command (for use without the jaria launcher). */
  public static void main(String[] args) {
    System.exit(new CommandLine(new SimViewCommand()).execute(args));
  }
}
