package org.jaria.tools.sim;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.geom.ArPose;
import org.jaria.map.MapNames;
import org.jaria.sim.OdometryError;
import org.jaria.sim.RobotFactory;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.ServerPlan;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimServerOptions;
import org.jaria.sim.SimWorld;
import org.jaria.sim.StartPlace;
import org.jaria.sim.robot.SimProfile;
import org.jaria.tools.options.SecondsOption;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./jaria sim}: a headless simulator that any ARIA client can connect to, like MobileSim.
 * Prints where each robot listens, runs until Ctrl-C, a client's SIM_EXIT or the end of {@code
 * --seconds}, and then closes every port. The world runs in real time, {@code --speedup} times
 * faster, or {@code --unthrottled} (as fast as the machine can; the old name {@code --lockstep}
 * still works but says it is deprecated). Lockstep with a client, where simulated time passes only
 * as the client's program allows, is what {@code org.jaria.sim.client.SimulatedRobot} does in
 * tests.
 */
@Command(
    name = "sim",
    mixinStandardHelpOptions = true,
    description = {
      "Runs a simulated world with ARCOS robots on TCP ports 8101, 8102, ... (a MobileSim analogue).",
      "Connect any ARIA client (e.g. -remoteHost localhost -remoteRobotTcpPort 8101). Ctrl-C stops."
    })
public final class SimCommand implements Callable<Integer> {

  /**
   * MobileSim's spellings of {@link SimCommand}'s own options (see {@link #usesMobileSimOptions}).
   */
  private static final Set<String> MOBILESIM_SPELLINGS =
      Set.of(
          "-m",
          "-map",
          "-r",
          "-robot",
          "--srisim-compat",
          "--no-srisim-laser-compat",
          "--ignore-command",
          "--cwd");

  @Spec private CommandSpec spec;

  @Mixin MobileSimOptions mobileSim = new MobileSimOptions();

  /** --web, --allow-control, --record: watch the world in a browser. */
  @Mixin org.jaria.tools.web.WebOption web = new org.jaria.tools.web.WebOption();

  @Option(
      names = {"-m", "--map", "-map"},
      paramLabel = "FILE",
      description =
          "ArMap .map file, or a bundled map name (office, hall, columbia); default: office")
  String map;

  @Option(
      names = {"-r", "--robot", "-robot"},
      paramLabel = "MODEL[:NAME]",
      description =
          "Robot model to add, optionally with its name (repeatable): p3dx-sh, p3at-sh, p2dx,"
              + " amigo, ...")
  List<String> robots = new ArrayList<>();

  @Option(
      names = "--robots",
      paramLabel = "N",
      description = "Number of robots (of the last --robot model, p3dx-sh by default)")
  Integer robotCount;

  @Option(
      names = {"-p", "--port"},
      description = "TCP port of the first robot (default ${DEFAULT-VALUE})")
  int port = SimOptions.DEFAULT_PORT;

  @Option(names = "--speedup", paramLabel = "X", description = "Run X times faster than real time")
  Double speedup;

  @Option(
      names = "--unthrottled",
      description =
          "No wall-clock pacing: ticks run back to back, as fast as the machine can (simulated"
              + " time still passes in whole ticks)")
  boolean unthrottled;

  /** The old name of --unthrottled: it never meant lockstep with a client. */
  @Option(names = "--lockstep", hidden = true, description = "Deprecated: use --unthrottled")
  boolean lockstep;

  @Option(
      names = "--seconds",
      paramLabel = "S",
      converter = SecondsOption.Fractional.class,
      description = "Stop after S seconds of simulated time (default and 0: run until Ctrl-C)")
  Double seconds;

  @Option(names = "--seed", description = "Random seed (default ${DEFAULT-VALUE})")
  long seed = 1;

  @Option(
      names = "--odometry-error",
      paramLabel = "SPEC",
      description =
          "Odometry error: none, constant:T,R, random:T,R, random_each_update:T,R or"
              + " random_init:T,R (per metre, per radian), e.g. random:0.02,0.05 (default: the"
              + " profile's: none for pioneer, random_each_update:0.0075,0.0075 for mobilesim)")
  String odometryError;

  @Option(
      names = "--profile",
      paramLabel = "mobilesim|pioneer",
      description =
          "Behave as MobileSim (ray sonar, all 16 readings per SIP, motors on, MobileSim's"
              + " CONFIGpac, drifting odometry, no gripper) or as a real Pioneer (sonar cone and"
              + " cycle, motors off until enabled, the model's CONFIGpac, exact odometry). Default:"
              + " mobilesim when the command line uses MobileSim's own options (-m, -r, --nomap,"
              + " --start, --nogui, ...), else pioneer")
  String profileName;

  @Option(names = "--sip-cycle", paramLabel = "MS", description = "SIP cycle, ms (default 100)")
  int sipCycle = 100;

  @Option(names = "--watchdog-warn-only", description = "The watchdog warns instead of stopping")
  boolean watchdogWarnOnly;

  @Option(names = "--no-specular", description = "Sonar sees walls at any angle")
  boolean noSpecular;

  @Option(
      names = "--laser",
      description =
          "Give every robot a simulated laser (the models MobileSim gives a laser, e.g. p3dx-sh,"
              + " carry one anyway)")
  boolean laser;

  @Option(names = "--no-laser", description = "No robot carries a laser")
  boolean noLaser;

  @Option(
      names = "--ptz-type",
      paramLabel = "TYPE",
      description =
          "The camera or pan-tilt unit on every robot's AUX1 port, by ARIA's PTZType names: vcc4"
              + " (the pioneer profile's default), sony, dpptu or none (the mobilesim profile's"
              + " default: MobileSim simulates no camera)")
  String ptzType;

  /** The old switch for what is now the default (SRISim laser commands on). */
  @Option(
      names = "--legacy-laser-commands",
      hidden = true,
      description = "Deprecated: the SRISim laser commands are on by default")
  boolean legacyLaserCommands;

  @Option(
      names = "--no-srisim-laser-compat",
      description =
          "Commands 35-38 keep their ARCOS meanings (ADSEL, GRIPPERVAL, GRIPREQUEST, GYROCALCW)"
              + " instead of setting up the laser as SRISim's laser commands do (MobileSim's"
              + " option; ARIA's ArSimulatedLaser then cannot start the laser)")
  boolean noSrisimLaserCompat;

  @Option(
      names = "--srisim-compat",
      description =
          "Also accept SRISim's other old commands: 62 exits, 66/67 set the true x/y, 69 resets"
              + " the robot (MobileSim's option; 62 is also ARCOS's BATTERYINFO)")
  boolean srisimCompat;

  @Option(
      names = "--cwd",
      paramLabel = "DIR",
      description =
          "Folder client programs may load maps from (SIM_CTRL), from any machine; paths are"
              + " relative to it, and absolute paths, '..' outside it, links out of it and files"
              + " that are not regular files are refused (default: the working directory, for"
              + " clients on this machine only)")
  Path cwd;

  @Option(
      names = "--ignore-command",
      paramLabel = "N",
      description =
          "Ignore client command number N (repeatable), as MobileSim: e.g. 239 SIM_EXIT, 236"
              + " SIM_CTRL (map loading), 224 SIM_SET_POSE (teleport)")
  List<Integer> ignoreCommands = new ArrayList<>();

  private final CountDownLatch stop = new CountDownLatch(1);
  private final AtomicInteger exitCode = new AtomicInteger();
  private final java.util.concurrent.atomic.AtomicBoolean summaryPrinted =
      new java.util.concurrent.atomic.AtomicBoolean();

  /**
   * Builds the world the options describe (not listening, not running).
   *
   * @throws ParameterException if an option value is wrong (the message says what to use)
   * @throws IOException if the map file cannot be read or parsed
   */
  public SimWorld createWorld() throws IOException {
    SimOptions options = buildOptions();
    SimWorld world = openMap(options);
    try {
      world.setBindAddress(mobileSim.bindAddress());
      StartPlace start = mobileSim.startPlace();
      SplittableRandom rng = new SplittableRandom(seed);
      List<String> specs = robotModels();
      List<String> factories = mobileSim.robotFactories;
      ServerPlan plan = new ServerPlan(port, factories.size(), specs.size());
      for (int i = 0; i < factories.size(); i++) {
        // MobileSim starts each factory robot at the start place (random: a new one each time)
        world.addRobotFactory(
            robotOptions(factories.get(i)),
            plan.factoryPort(i),
            m -> start == null ? null : start.poseFor(0, m, rng));
      }
      boolean row = options.profile() == SimProfile.MOBILESIM;
      for (int i = 0; i < specs.size(); i++) {
        RobotOptions o = robotOptions(specs.get(i)).withPort(plan.robotPort(i));
        ArPose pose;
        if (start != null) {
          pose = start.poseFor(i, world.getMap(), rng);
        } else if (row && i > 0) {
          // MobileSim stands its robots in a row below the map's home, 1 m apart
          pose = StartPlace.inRow(world.getMap().home(), i);
        } else {
          pose = null; // the home, or the nearest free spot around it
        }
        world.addRobot(pose == null ? o : o.withStartPose(pose));
      }
    } catch (IllegalArgumentException e) {
      world.close();
      throw new ParameterException(spec.commandLine(), e.getMessage());
    }
    return world;
  }

  private SimWorld openMap(SimOptions options) throws IOException {
    if (map == null && mobileSim.noMap) {
      return SimWorld.empty(options);
    }
    String m = map == null ? "office" : map;
    String bundled = MapNames.bundledName(m);
    if (bundled != null) {
      return SimWorld.bundled(bundled, options);
    }
    Optional<String> problem = MapNames.problem(m);
    if (problem.isPresent()) {
      throw new IOException(problem.get());
    }
    return SimWorld.load(Path.of(m), options);
  }

  /**
   * The options of one robot given as {@code MODEL} or {@code MODEL:NAME}, as the laser and SRISim
   * options say.
   */
  RobotOptions robotOptions(String robotSpec) {
    if (laser && noLaser) {
      throw new ParameterException(spec.commandLine(), "choose either --laser or --no-laser");
    }
    int colon = robotSpec.indexOf(':');
    String model = colon < 0 ? robotSpec : robotSpec.substring(0, colon);
    RobotOptions o = RobotOptions.of(model);
    if (colon >= 0 && colon + 1 < robotSpec.length()) {
      o = o.withName(robotSpec.substring(colon + 1));
    }
    if (laser || noLaser) {
      o = o.withLaser(laser);
    }
    return o.withLegacyLaserCommands(o.laser() && !noSrisimLaserCompat)
        .withSrisimCompat(srisimCompat)
        .withPtzType(
            ptzType != null ? ptzType : profile() == SimProfile.MOBILESIM ? "none" : "vcc4")
        .withGripper(profile().gripperByDefault());
  }

  /**
   * The profile: {@code --profile} if given, else {@code mobilesim} when the command line is
   * MobileSim's (see {@link #usesMobileSimOptions()}), else {@code pioneer}.
   *
   * @throws ParameterException if {@code --profile} names no profile
   */
  public SimProfile profile() {
    if (profileName != null) {
      try {
        return SimProfile.parse(profileName);
      } catch (IllegalArgumentException e) {
        throw new ParameterException(spec.commandLine(), e.getMessage());
      }
    }
    return usesMobileSimOptions() ? SimProfile.MOBILESIM : SimProfile.PIONEER;
  }

  /**
   * Whether the command line uses an option JAria has only because MobileSim has it: any of {@link
   * MobileSimOptions}, the spellings {@code -m}, {@code -map}, {@code -r}, {@code -robot}, and
   * {@code --srisim-compat}, {@code --no-srisim-laser-compat}, {@code --ignore-command}, {@code
   * --cwd}. JAria's own {@code --map}, {@code --robot} and {@code -p}/{@code --port} do not count.
   */
  boolean usesMobileSimOptions() {
    if (spec.commandLine().getParseResult() == null) {
      return false;
    }
    Set<String> names = new HashSet<>(MOBILESIM_SPELLINGS);
    for (OptionSpec o : spec.mixins().get("mobileSim").options()) {
      names.addAll(List.of(o.names()));
    }
    for (String a : spec.commandLine().getParseResult().originalArgs()) {
      int eq = a.indexOf('=');
      if (names.contains(eq > 0 ? a.substring(0, eq) : a)) {
        return true;
      }
    }
    return false;
  }

  /** The robot models to add, in order (none by default if there are robot factories). */
  List<String> robotModels() {
    boolean none = robots.isEmpty() && mobileSim.robotFactories.isEmpty();
    List<String> models = new ArrayList<>(none ? List.of("p3dx-sh") : robots);
    if (robotCount != null) {
      if (robotCount < 1 || robotCount > 1000) {
        throw new ParameterException(
            spec.commandLine(), "--robots must be 1..1000, was " + robotCount);
      }
      String last = models.isEmpty() ? "p3dx-sh" : models.get(models.size() - 1);
      while (models.size() < robotCount) {
        models.add(last);
      }
    }
    return models;
  }

  /** The world options the command line describes. */
  SimOptions buildOptions() {
    if (isUnthrottled() && speedup != null) {
      throw new ParameterException(spec.commandLine(), "choose either --speedup or --unthrottled");
    }
    if (speedup != null && !(speedup > 0)) {
      throw new ParameterException(
          spec.commandLine(), "--speedup must be positive, was " + speedup);
    }
    if (seconds != null && seconds == 0) {
      seconds = null; // 0 is no limit, as in every command with --seconds
    }
    SimProfile profile = profile();
    OdometryError err;
    try {
      if (mobileSim.noError) {
        err = OdometryError.NONE;
      } else if (odometryError != null) {
        err = OdometryError.parse(odometryError);
      } else if (mobileSim.odomErrorMode != null) {
        err = OdometryError.ofMobileSimMode(mobileSim.odomErrorMode);
      } else {
        err = profile.odometryError();
      }
    } catch (IllegalArgumentException e) {
      throw new ParameterException(spec.commandLine(), e.getMessage());
    }
    try {
      Integer tick = mobileSim.tickMillis();
      return SimOptions.builder()
          .profile(profile)
          .server(serverOptions())
          .tickMillis(tick != null ? tick : 10)
          .seed(seed)
          .basePort(port)
          .sipCycleMillis(sipCycle)
          .watchdogWarnOnly(watchdogWarnOnly)
          .odometryError(err)
          .sonar(noSpecular ? profile.sonar().withSpecular(false) : profile.sonar())
          .build();
    } catch (IllegalArgumentException e) {
      throw new ParameterException(spec.commandLine(), e.getMessage());
    }
  }

  /** What --cwd and --ignore-command ask of the robots' ports. */
  private SimServerOptions serverOptions() {
    SimServerOptions so = SimServerOptions.DEFAULTS.withIgnoredCommands(Set.copyOf(ignoreCommands));
    if (cwd != null) {
      if (!Files.isDirectory(cwd)) {
        throw new ParameterException(
            spec.commandLine(), "--cwd " + cwd + " is not a folder; give an existing folder");
      }
      so = so.withMapFolder(cwd, so.maxMapBytes());
    }
    return so;
  }

  private boolean isUnthrottled() {
    return unthrottled || lockstep;
  }

  /**
   * The speed-up the options ask for: the {@code --speedup} value, 1 by default, or 0 for {@code
   * --unthrottled} (as fast as possible).
   */
  public double pacing() {
    if (isUnthrottled()) {
      return 0;
    }
    if (speedup != null) {
      return speedup;
    }
    Double updates = mobileSim.speedup();
    return updates != null ? updates : 1;
  }

  /**
   * Says, on {@code err}, that {@code --lockstep} is the old name of {@code --unthrottled}, if it
   * was used.
   */
  public void noteDeprecatedOptions(PrintWriter err) {
    mobileSim.meaninglessNames.clear();
    if (spec.commandLine().getParseResult() != null) {
      // Every name of the meaningless options belongs to one option; find which were given.
      OptionSpec meaningless = spec.findOption("--nogui");
      java.util.Set<String> names = java.util.Set.of(meaningless.names());
      for (String a : spec.commandLine().getParseResult().originalArgs()) {
        if (names.contains(a)) {
          mobileSim.meaninglessNames.add(a);
        }
      }
    }
    mobileSim.noteIgnored(err);
    if (legacyLaserCommands) {
      err.println("note: --legacy-laser-commands is the default now (SRISim laser commands)");
    }
    if (lockstep) {
      err.println(
          "note: --lockstep is deprecated; it means --unthrottled (ticks as fast as possible), not"
              + " lockstep with a client. Use --unthrottled.");
      err.flush();
    }
  }

  /**
   * Points the log at {@code --log-file} and sets its level from {@code --verbose} / {@code
   * --less-verbose} (JAria's simple logger reads both when the first log line is made).
   */
  void configureLogging() {
    if (mobileSim.logFile != null) {
      System.setProperty("org.slf4j.simpleLogger.logFile", mobileSim.logFile.toString());
    }
    if (mobileSim.verbose) {
      System.setProperty("org.slf4j.simpleLogger.defaultLogLevel", "debug");
    } else if (mobileSim.lessVerbose) {
      System.setProperty("org.slf4j.simpleLogger.defaultLogLevel", "error");
    }
  }

  @Override
  public Integer call() throws IOException {
    PrintWriter out = spec.commandLine().getOut();
    configureLogging();
    noteDeprecatedOptions(spec.commandLine().getErr());
    SimWorld world = createWorld();
    // On Ctrl-C the JVM exits once the hooks end, so the hook itself closes the world.
    Thread hook =
        new Thread(
            () -> {
              stop.countDown();
              summaryOnce(world, out);
              world.close();
            },
            "jaria-sim-shutdown");
    world.setExitHandler(
        code -> {
          exitCode.set(code);
          stop.countDown();
        });
    org.jaria.tools.web.WebView view = null;
    try {
      world.listen();
    } catch (IOException | RuntimeException e) {
      // Nothing ran: the error (a port in use) is all there is to say, no summary before it.
      world.close();
      throw e;
    }
    try {
      printListening(world, out);
      out.printf(
          "profile %s; map %s, %s; %s%n",
          world.getOptions().profile().cliName(),
          map != null ? map : (mobileSim.noMap ? "none (empty world)" : "office"),
          isUnthrottled() ? "unthrottled" : "speed-up " + pacing(),
          seconds == null
              ? "Ctrl-C stops"
              : "stops after " + seconds + " s of simulated time (or Ctrl-C)");
      out.flush();
      view = startWebView(world, out);
      if (seconds != null) {
        long end = world.getClock().nanoTime() + Math.round(seconds * 1e9);
        world.addStepListener(
            () -> {
              if (world.getClock().nanoTime() >= end) {
                stop.countDown();
              }
            });
      }
      Runtime.getRuntime().addShutdownHook(hook);
      world.startRealTime(pacing());
      stop.await();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      if (view != null) {
        view.close();
      }
      summaryOnce(world, out);
      world.close();
      try {
        Runtime.getRuntime().removeShutdownHook(hook);
      } catch (IllegalStateException shuttingDown) {
        // the JVM is exiting through Ctrl-C: the hook is running, nothing to remove
      }
      out.println("simulator stopped");
      out.flush();
    }
    return exitCode.get();
  }

  /** The web view --web or --record asks for (the clock controls only with --allow-control). */
  private org.jaria.tools.web.WebView startWebView(SimWorld world, PrintWriter out)
      throws IOException {
    String mapName = map != null ? map : mobileSim.noMap ? null : "office";
    var control = new org.jaria.web.source.SimulationControl(world, pacing());
    var source =
        new org.jaria.web.source.SimWorldSource(
            world,
            control,
            org.jaria.tools.web.WebOption.mapOrNull(mapName),
            mapName == null ? "empty" : Path.of(mapName).getFileName().toString());
    return web.start(
        "jaria sim · " + (mapName == null ? "empty world" : Path.of(mapName).getFileName()),
        source,
        new org.jaria.web.control.Controls(null, control),
        out);
  }

  /**
   * One line per robot factory and per robot saying on which TCP port it listens (after {@link
   * SimWorld#listen()}), so that a script can find the ports.
   */
  public static void printListening(SimWorld world, PrintWriter out) {
    for (RobotFactory f : world.getRobotFactories()) {
      out.printf(
          "robot factory for %s listening on TCP port %d (a new robot for each client)%n",
          f.getModel(), f.getPort());
    }
    for (SimRobot r : world.getRobots()) {
      out.printf(
          "robot %s (%s) listening on TCP port %d%n",
          r.getName(), r.getModel().getSubtype(), r.getPort());
    }
  }

  /**
   * Prints the summary once, from whichever of the main thread and the Ctrl-C hook comes first;
   * synchronized so that the hook returns (and the JVM halts) only once the lines are out.
   */
  private synchronized void summaryOnce(SimWorld world, PrintWriter out) {
    if (summaryPrinted.compareAndSet(false, true)) {
      printSummary(world, out);
    }
  }

  /**
   * One line per robot on stopping: where it started, where it is, how many clients opened it (so a
   * script can tell whether a client drove it).
   */
  static void printSummary(SimWorld world, PrintWriter out) {
    for (SimRobot r : world.getRobots()) {
      ArPose a = r.getStartPose();
      ArPose b = r.getTruePose();
      out.printf(
          java.util.Locale.ROOT,
          "robot %s: started at %.0f,%.0f,%.0f; now at %.0f,%.0f,%.0f; moved %.0f mm from the"
              + " start; drove %.0f mm; %d client session(s)%n",
          r.getName(),
          a.x(),
          a.y(),
          a.th(),
          b.x(),
          b.y(),
          b.th(),
          Math.hypot(b.x() - a.x(), b.y() - a.y()),
          r.getDistanceDriven(),
          r.getSessionCount());
    }
    for (RobotFactory f : world.getRobotFactories()) {
      out.printf(
          "robot factory for %s: %d robot(s) made, %d in the world%n",
          f.getModel(), f.getRobotsMade(), f.getRobots().size());
    }
    out.flush();
  }

  /** Asks a running {@link #call()} to stop (as Ctrl-C does). */
  public void requestStop() {
    stop.countDown();
  }
}
