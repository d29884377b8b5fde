package org.jaria.tools.sim;

import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.sim.StartPlace;
import picocli.CommandLine.Option;

/**
 * The options of MobileSim's command line that {@code ./jaria sim} takes besides its own (a picocli
 * mixin of {@link SimCommand}), so that a script that starts MobileSim starts JAria's simulator
 * unchanged. {@code -m/--map}, {@code -r/--robot} and {@code -p/--port} are {@link SimCommand}'s
 * own options under MobileSim's names too. Options that mean nothing here (graphics, crash
 * handling, network discovery...) are accepted and {@link #noteIgnored say so} once.
 */
public final class MobileSimOptions {

  @Option(
      names = {"--nomap", "-nomap"},
      description = "Start with an empty world (MobileSim: ignored if -m is also given)")
  boolean noMap;

  @Option(
      names = {"-R", "--robot-factory", "-robot-factory"},
      paramLabel = "MODEL",
      description =
          "A robot factory (repeatable): each client that connects to its port gets a new robot of"
              + " MODEL, removed when the client disconnects (MobileSim's -R; ports from -p on,"
              + " before the -r robots')")
  List<String> robotFactories = new ArrayList<>();

  @Option(
      names = {"--start", "-start"},
      paramLabel = "x,y,th|outside|random",
      description =
          "Where robots start: x,y,th (mm, deg), outside (2 m left of the map) or random (within"
              + " the map, from --seed); every robot, the next ones 1 m below (-y) the one before")
  String start;

  @Option(
      names = {"--bind-to-address", "-bind-to-address"},
      paramLabel = "ADDR",
      description = "Listen for clients only on the interface with this address (default: all)")
  String bindAddress;

  @Option(
      names = {"-l", "--log-file", "-log-file"},
      paramLabel = "FILE",
      description = "Write the simulator's log to FILE instead of standard error")
  Path logFile;

  @Option(
      names = {"--log-file-max-size", "-log-file-max-size"},
      paramLabel = "BYTES",
      description = "Accepted; the log file is not rotated")
  Long logFileMaxSize;

  @Option(
      names = {"--update-interval", "-update-interval"},
      paramLabel = "MS",
      description = "Wall-clock time between simulation updates, ms (with --update-sim-time: pace)")
  Integer updateInterval;

  @Option(
      names = {"--update-sim-time", "-update-sim-time"},
      paramLabel = "MS",
      description = "Simulated time each update advances, ms (default: --update-interval, else 10)")
  Integer updateSimTime;

  @Option(
      names = {"--resolution", "-resolution"},
      paramLabel = "MM",
      description = "Accepted; JAria's sensors and collisions use exact geometry, not a grid")
  Double resolution;

  @Option(
      names = {"--verbose", "-verbose"},
      description = "Log more (debug messages)")
  boolean verbose;

  @Option(
      names = {"--less-verbose", "-less-verbose"},
      description = "Log less (warnings and errors only)")
  boolean lessVerbose;

  @Option(
      names = {"--warn-unsupported-commands", "-warn-unsupported-commands"},
      description = "Accepted; JAria always warns once per command number it does not carry out")
  boolean warnUnsupported;

  @Option(
      names = {"--no-error", "-no-error"},
      description = "Exact odometry (the pioneer profile's default; see --odometry-error)")
  boolean noError;

  @Option(
      names = {"--odom-error-mode", "-odom-error-mode"},
      paramLabel = "MODE",
      description =
          "MobileSim's odometry error modes: random_each_update (the mobilesim profile's"
              + " default), random_init, constant (0.0075 per metre and per radian) or none")
  String odomErrorMode;

  /** MobileSim options with no meaning in a headless simulator without crash handlers. */
  @Option(
      names = {
        "--noninteractive",
        "--non-interactive",
        "-noninteractive",
        "--no-graphics",
        "--nographics",
        "--disable-graphics",
        "--no-gui",
        "--nogui",
        "--disable-gui",
        "-nogui",
        "--lite-graphics",
        "--litegraphics",
        "--html",
        "--maximize",
        "--maximize-gui",
        "--minimize",
        "--minimize-gui",
        "--fullscreen",
        "--fullscreen-gui",
        "--daemonize",
        "--no-crash-handler",
        "--disable-crash-handler",
        "--no-crash-debug",
        "--disable-crash-debug",
        "--no-crash-restart",
        "--disable-crash-restart",
        "--restarting-after-crash",
        "--no-menu",
        "--no-messages",
        "--no-network-discovery",
        "--log-packets-received",
        "--log-movement-sent",
        "--echo-stage-worldfile"
      },
      hidden = true,
      description = "MobileSim options that mean nothing here (accepted; a note says so)")
  List<Boolean> meaningless = new ArrayList<>();

  /** The names of the meaningless options given, in order (filled by {@link SimCommand}). */
  final List<String> meaninglessNames = new ArrayList<>();

  /**
   * The bind address, or null for all interfaces.
   *
   * @throws IllegalArgumentException naming the address if it cannot be resolved
   */
  InetAddress bindAddress() {
    if (bindAddress == null) {
      return null;
    }
    try {
      return InetAddress.getByName(bindAddress);
    } catch (UnknownHostException e) {
      throw new IllegalArgumentException(
          "--bind-to-address " + bindAddress + " is not an address of this machine", e);
    }
  }

  /** The {@code --start} place, or null if none was given. */
  StartPlace startPlace() {
    return start == null ? null : StartPlace.parse(start);
  }

  /**
   * The simulation tick the update options ask for, ms, or null for the default: {@code
   * --update-sim-time}, else {@code --update-interval}.
   */
  Integer tickMillis() {
    Integer t = updateSimTime != null ? updateSimTime : updateInterval;
    if (t != null && (t < 1 || t > 1000)) {
      throw new IllegalArgumentException("--update-sim-time/--update-interval must be 1..1000 ms");
    }
    return t;
  }

  /**
   * The speed-up the update options ask for ({@code --update-sim-time} over {@code
   * --update-interval}), or null if they do not both set it.
   */
  Double speedup() {
    if (updateInterval == null || updateSimTime == null) {
      return null;
    }
    if (updateInterval <= 0) {
      return 0.0; // MobileSim: no wait between updates
    }
    return updateSimTime / (double) updateInterval;
  }

  /** Says once, on {@code err}, which given options are accepted without effect. */
  void noteIgnored(PrintWriter err) {
    for (String name : meaninglessNames) {
      err.println("note: " + name + " (a MobileSim option) has no meaning here; ignored");
    }
    if (resolution != null) {
      err.println(
          "note: --resolution is accepted but JAria's sensors and collisions use exact geometry");
    }
    if (logFileMaxSize != null) {
      err.println("note: --log-file-max-size is accepted; JAria does not rotate its log file");
    }
    if (warnUnsupported) {
      err.println("note: --warn-unsupported-commands: JAria warns once per command number anyway");
    }
    err.flush();
  }
}
