package org.jaria.tools.guiserver;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.image.Cameras;
import org.jaria.acts.image.ImageSequenceSource;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.StillImageSource;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.RobotAddress;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.client.Passwords;
import org.jaria.net.forward.ArHybridForwarderVideo;
import org.jaria.net.forward.ForwarderStats;
import org.jaria.net.guiserver.GuiServer;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ArServerUserInfo;
import org.jaria.net.server.Authenticator;
import org.jaria.net.server.MapFolder;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.modes.ArServerModes;
import org.jaria.net.video.JpegVideo;
import org.jaria.ptz.ArVCC4;
import org.jaria.robot.ArRobot;
import org.jaria.simguiserver.ScanMapping;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.jaria.tools.options.SecondsOption;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria demo guiserver}: the thesis's guiServer (§6.1). Connects to a robot (or runs an
 * embedded simulator), localizes it with the sonar, plans paths, and serves the robot's state,
 * sonar, map, localization, path, information strings, modes, configuration and camera to monitors
 * ({@code jaria monitor}) until Ctrl-C.
 */
@Command(
    name = "guiserver",
    mixinStandardHelpOptions = true,
    sortOptions = false,
    // One paragraph per element: picocli wraps each to the terminal's width by itself.
    description = {
      "The thesis's guiServer (§6.1): sonar localization, path planning and a network server"
          + " for monitors (./jaria monitor). Without --remote it drives an embedded simulator."
    })
public final class GuiServerCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--map",
      paramLabel = "FILE",
      description =
          "The map: a .map file or a bundled map (office, hall, columbia). Default: office.")
  String map = "office";

  @Option(
      names = "--map-dir",
      paramLabel = "DIR",
      description =
          "Clients may switch the server to a map of this folder (ARIA's Files/Map parameter, as"
              + " changeMapOnServer sets it), or to a bundled map. Default: the --map file's"
              + " folder (the bundled maps only for a bundled --map).")
  Path mapDir;

  @Option(
      names = "--remote",
      paramLabel = "HOST[:PORT]|DEVICE",
      description =
          "Drive this robot or simulator (port 8101 if absent; a serial device such as"
              + " /dev/ttyS0 works too) instead of an embedded one.")
  String remote;

  @Option(
      names = "--serial",
      paramLabel = "DEVICE",
      description =
          "Drive the robot on this serial port (e.g. /dev/ttyS0: the thesis's set-up, the"
              + " program on the robot's own computer) instead of an embedded simulator.")
  String serial;

  @Option(
      names = "--baud",
      description = "Serial baud rate with --serial (default ${DEFAULT-VALUE}).")
  int baud = ArSerialConnection.DEFAULT_BAUD;

  @Option(
      names = "--camera",
      paramLabel = "DEVICE",
      description =
          "With --remote or --serial: serve this camera's video (an OpenCV index such as 0, or a"
              + " device path).")
  String camera;

  @Option(
      names = "--video",
      paramLabel = "FILE|DIR",
      description =
          "With --remote or --serial: serve this picture, or the pictures of this folder in turn,"
              + " as the video (a camera stand-in for tests and demonstrations).")
  Path video;

  @Option(
      names = "--ptz",
      paramLabel = "TYPE",
      description =
          "With --remote or --serial: the robot's pan-tilt-zoom camera on its AUX port (vcc4: a"
              + " Canon VC-C4), which clients may then point (ARIA's camera requests, camera"
              + " Cam1). The embedded simulator's VC-C4 is served unless --no-camera.")
  String ptz;

  @Option(
      names = "--forward-video",
      paramLabel = "HOST[:PORT]",
      description =
          "Forward the video of this ArNetworking video server (port 7070 if absent: the SAV"
              + " server of jaria acts) to monitors, as ARIA's serverDemo does; it replaces the"
              + " camera.")
  String forwardVideo;

  @Option(
      names = "--port",
      description = "TCP port to serve monitors on (default ${DEFAULT-VALUE}; 0: any free one).")
  int port = 7272;

  @Option(
      names = "--user-file",
      paramLabel = "FILE",
      description =
          "ArNetworking's user file: users, passwords and groups (see aria-net/PROTOCOL.md §4).")
  Path userFile;

  @Option(
      names = "--password",
      paramLabel = "SECRET",
      description =
          "One password for every user name (visible to other users of this computer: prefer"
              + " --password-file or the JARIA_NET_PASSWORD environment variable).")
  String password;

  @Option(
      names = "--password-file",
      paramLabel = "FILE",
      description = "Read the password from the first line of FILE (which only you may read).")
  Path passwordFile;

  @Option(
      names = "--bind",
      paramLabel = "ADDRESS",
      description =
          "Interface to listen on (default: all interfaces with a login, this computer only"
              + " without one; beyond this computer without a login only with --no-login).")
  String bind;

  @Option(
      names = "--no-login",
      description =
          "Serve without a login beyond this computer (with --bind): anybody who can reach the"
              + " port may then drive the robot. Only on a network you trust completely.")
  boolean noLogin;

  @Option(
      names = "--speed",
      paramLabel = "X",
      description = "Embedded simulator speed, times real time (default ${DEFAULT-VALUE}).")
  double speed = 1;

  @Option(names = "--robot", description = "Embedded robot model (default ${DEFAULT-VALUE}).")
  String model = "p3dx-sh";

  @Option(names = "--seed", description = "Simulator and localization seed (default 1).")
  long seed = 1;

  @Option(names = "--no-camera", description = "Do not serve the simulated camera.")
  boolean noCamera;

  @Option(
      names = "--mapping",
      description =
          "Offer ArNetworking's mapping services with the simulator's laser: clients (jaria"
              + " monitor) start and end a scan log in the map folder (--map-dir), and its map is"
              + " built there when the scan ends.")
  boolean mapping;

  @Option(
      names = "--seconds",
      converter = SecondsOption.Whole.class,
      description = "Stop after this many seconds (default and 0: run until Ctrl-C).")
  int seconds;

  /** --web, --allow-control, --record: watch (and drive) it in a browser. */
  @picocli.CommandLine.Mixin
  org.jaria.tools.web.WebOption web = new org.jaria.tools.web.WebOption();

  @Override
  @SuppressWarnings("try") // the web view only needs closing
  public Integer call() {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    try {
      ServerOptions options = serverOptions();
      ArMap m = loadMap(map);
      String mapName = Path.of(map).getFileName().toString();
      if (remote != null && serial != null) {
        throw new IllegalArgumentException("give --remote or --serial, not both");
      }
      if (camera != null && video != null) {
        throw new IllegalArgumentException("give --camera or --video, not both");
      }
      if (forwardVideo != null && (camera != null || video != null)) {
        throw new IllegalArgumentException(
            "give --forward-video or --camera/--video, not both: each serves sendVideo");
      }
      if (forwardVideo != null) {
        forwardPort(); // a wrong address is said before anything starts
      }
      if (ptz != null && !ptz.equalsIgnoreCase("vcc4")) {
        throw new IllegalArgumentException("--ptz knows vcc4 (a Canon VC-C4), not '" + ptz + "'");
      }
      if (remote != null || serial != null) {
        return runOnRobot(m, mapName, options, out);
      }
      if (camera != null || video != null || ptz != null) {
        throw new IllegalArgumentException(
            "--camera, --video and --ptz are for a real robot (--remote or --serial); the"
                + " embedded simulator serves its own camera and VC-C4 (or none with"
                + " --no-camera)");
      }
      try (SimulatedGuiServer s =
              SimulatedGuiServer.start(
                  new SimulatedGuiServer.Options(
                      m,
                      mapName,
                      model,
                      seed,
                      options,
                      ArnlNavigation.Mode.THREADED,
                      speed,
                      !noCamera && forwardVideo == null),
                  mapFolder());
          ArHybridForwarderVideo forwarder = forwarder(s.gui().getServer(), out);
          ScanMapping scans = scanMapping(s.gui(), s.robot(), out)) {
        out.printf(
            Locale.ROOT,
            "guiServer: embedded simulator, a %s on %s, %s%n",
            model,
            map,
            speed == 1 ? "real time" : speed + " × real time");
        report(out, s.wasLocalized(), s.robot(), s.nav());
        var nv =
            org.jaria.tools.web.NavigationView.simulated(
                s.world(), s.sim().sim().getName(), s.nav(), m, mapName, speed);
        try (var view =
            web.start("guiServer · " + mapName, nv.source(), nv.controls(), out, nv.driver())) {
          return serve(s.gui(), s.robot(), forwarder, out);
        }
      }
    } catch (IllegalArgumentException | IllegalStateException | IOException e) {
      err.println("guiserver: " + e.getMessage());
      err.flush();
      return 2;
    }
  }

  ServerOptions serverOptions() throws IOException {
    String secret =
        Passwords.resolve(
            password, passwordFile, userFile == null ? System.getenv() : java.util.Map.of());
    if (userFile != null && secret != null) {
      throw new IllegalArgumentException("give --user-file or a password, not both");
    }
    Authenticator auth =
        userFile != null
            ? ArServerUserInfo.readFile(userFile)
            : secret != null ? Authenticator.sharedSecret(secret) : Authenticator.open();
    if (noLogin && !auth.isOpen()) {
      throw new IllegalArgumentException(
          "give --no-login or a password (or --user-file), not both");
    }
    if (auth.isOpen() && !noLogin && bind != null && !isLoopback(bind)) {
      throw new IllegalArgumentException(
          "--bind "
              + bind
              + " without a password would let anybody who can reach port "
              + port
              + " drive the robot: give --password-file FILE or --user-file FILE (see"
              + " docs/networking.md), or add --no-login if that is really meant");
    }
    return ServerOptions.builder()
        .serverName("guiServer")
        .port(port)
        .bindAddress(bind)
        .authenticator(auth)
        .openBeyondLoopback(noLogin)
        .build();
  }

  private static boolean isLoopback(String address) throws IOException {
    return java.net.InetAddress.getByName(address).isLoopbackAddress();
  }

  /**
   * What the server's address and login mean, said plainly: "Listening on 0.0.0.0:7272 (NO LOGIN:
   * anybody who can reach this port may drive the robot)".
   */
  static String listeningLine(String address, int port, boolean open) {
    boolean local;
    try {
      local = java.net.InetAddress.getByName(address).isLoopbackAddress();
    } catch (java.net.UnknownHostException e) {
      local = false;
    }
    String what;
    if (open) {
      what =
          local
              ? "no login needed; this computer only: give --password-file or --user-file to"
                  + " serve others"
              : "NO LOGIN: anybody who can reach this port may drive the robot";
    } else {
      what =
          local
              ? "login required; this computer only"
              : "login required; the login is weak and nothing is encrypted: across a network you"
                  + " do not trust, see docs/networking.md";
    }
    return String.format(Locale.ROOT, "Listening on %s:%d (%s)", address, port, what);
  }

  /** The mapping services --mapping asks for, writing in the map folder; or null. */
  private ScanMapping scanMapping(GuiServer gui, ArRobot robot, PrintWriter out)
      throws IOException {
    if (!mapping) {
      return null;
    }
    Path folder = mapFolder().getFolder();
    if (folder == null) {
      throw new IllegalArgumentException(
          "--mapping writes scans and maps into the map folder: give --map-dir DIR");
    }
    ScanMapping m =
        ScanMapping.withSimulatedLaser(
            gui,
            robot,
            folder,
            status -> {
              out.println("Mapping: " + status);
              out.flush();
            });
    out.printf(Locale.ROOT, "Mapping: scans and their maps are written in %s%n", folder);
    return m;
  }

  /** The folder of --map-dir, else of the --map file (none for a bundled map). */
  private MapFolder mapFolder() throws IOException {
    if (mapDir != null) {
      return new MapFolder(mapDir);
    }
    Path file = Path.of(map);
    Path parent = file.toAbsolutePath().getParent();
    return new MapFolder(Files.isRegularFile(file) && parent != null ? parent : null);
  }

  static ArMap loadMap(String map) throws IOException {
    try {
      return ArMap.load(map);
    } catch (MapFormatException e) {
      throw new IllegalArgumentException("not a valid map: " + e.getMessage(), e);
    }
  }

  /** Where the robot is: --serial, or --remote (a host, host:port or serial device). */
  private RobotAddress robotAddress() {
    return serial != null ? RobotAddress.serial(serial, baud) : RobotAddress.parse(remote);
  }

  /** The video --camera or --video asks for, or null. */
  private JpegVideo openVideo() throws IOException {
    int w = 320;
    int h = 240;
    ImageSource source;
    String name;
    if (camera != null) {
      source = Cameras.open(camera, w, h);
      name = "Camera " + camera;
    } else if (video != null) {
      source =
          Files.isDirectory(video)
              ? ImageSequenceSource.ofDirectory(video, w, h, true)
              : StillImageSource.open(video, w, h);
      name = video.getFileName().toString();
    } else {
      return null;
    }
    return new JpegVideo(name, source.width(), source.height(), 5, source::nextFrame) {
      @Override
      public void close() {
        super.close();
        source.close();
      }
    };
  }

  @SuppressWarnings("try") // the web view only needs closing
  private int runOnRobot(ArMap m, String mapName, ServerOptions options, PrintWriter out)
      throws IOException {
    RobotAddress where = robotAddress();
    ArRobot robot = new ArRobot("robot");
    robot.setDeviceConnection(where.open(Clock.system(), "--remote"));
    if (!robot.blockingConnect()) {
      throw new IllegalStateException(
          "could not connect to the robot at " + where + ": " + robot.getConnectFailure());
    }
    robot.runAsync(true);
    try (JpegVideo cam = openVideo();
        ArnlNavigation nav = ArnlNavigation.create(robot, m, ArnlNavigation.Mode.THREADED, seed)) {
      robot.enableMotors();
      pause(Duration.ofMillis(1500));
      boolean localized = nav.localizeAtHome();
      out.printf(Locale.ROOT, "guiServer: robot %s at %s on %s%n", robot.getName(), where, map);
      if (cam != null) {
        out.printf(Locale.ROOT, "Serving video: %s%n", cam.getName());
      }
      report(out, localized, robot, nav);
      ArVCC4 unit = null;
      if (ptz != null) {
        unit = new ArVCC4(robot);
        unit.init();
        out.println("Serving the VC-C4 on the robot's AUX port as camera Cam1");
      }
      try (GuiServer gui =
          GuiServer.builder(robot)
              .options(options)
              .map(m, mapName)
              .localization(nav.localization())
              .pathPlanning(nav.pathPlanning())
              .config(nav.configRegistry())
              .video(cam)
              .ptz(unit)
              .mapChange(mapFolder(), nav::setMap)
              .build()) {
        nav.addCommands(gui.getCommands());
        var nv = org.jaria.tools.web.NavigationView.real(nav, m, mapName);
        try (ArHybridForwarderVideo forwarder = forwarder(gui.getServer(), out);
            ScanMapping scans = scanMapping(gui, robot, out);
            var view =
                web.start("guiServer · " + mapName, nv.source(), nv.controls(), out, nv.driver())) {
          gui.open();
          return serve(gui, robot, forwarder, out);
        }
      }
    } finally {
      robot.close();
    }
  }

  /** The video forwarder --forward-video asks for (its data added to {@code server}), or null. */
  private ArHybridForwarderVideo forwarder(ArServerBase server, PrintWriter out) {
    if (forwardVideo == null) {
      return null;
    }
    ArHybridForwarderVideo f =
        new ArHybridForwarderVideo(
            server,
            forwardHost(),
            forwardPort(),
            java.time.Duration.ofSeconds(2),
            System::nanoTime);
    out.printf(Locale.ROOT, "Forwarding video from %s%n", f.getSource());
    return f;
  }

  private String forwardHost() {
    int colon = forwardVideo.lastIndexOf(':');
    return colon < 0 ? forwardVideo : forwardVideo.substring(0, colon);
  }

  /** The port of --forward-video (ACTS's 7070 if it names none). */
  private int forwardPort() {
    int colon = forwardVideo.lastIndexOf(':');
    if (colon < 0) {
      return ArHybridForwarderVideo.DEFAULT_PORT;
    }
    try {
      int p = Integer.parseInt(forwardVideo.substring(colon + 1));
      if (p >= 1 && p <= 0xFFFF) {
        return p;
      }
    } catch (NumberFormatException e) {
      // said below
    }
    throw new IllegalArgumentException(
        "--forward-video wants HOST or HOST:PORT, got '" + forwardVideo + "'");
  }

  private static void report(PrintWriter out, boolean localized, ArRobot robot, ArnlNavigation n) {
    out.printf(
        Locale.ROOT,
        "Localized at home: %s, pose %s, score %.2f%n",
        localized ? "yes" : "NO (monitors can relocalize it)",
        robot.getPose(),
        n.getLocalizationTask().getLocalizationScore());
  }

  /** Prints where it listens, then a status line every 10 s until the time is up or Ctrl-C. */
  private int serve(
      GuiServer gui, ArRobot robot, ArHybridForwarderVideo forwarder, PrintWriter out) {
    var server = gui.getServer();
    boolean open = server.getOptions().authenticator().isOpen();
    // Where it really listens, not what was asked for.
    String shown = server.getAddress();
    out.println(listeningLine(shown, server.getPort(), open));
    out.printf(
        Locale.ROOT,
        "Watch it with: ./jaria monitor %s:%d%s%n",
        shown.equals("0.0.0.0") ? "HOST" : shown,
        server.getPort(),
        open ? "" : " --user NAME --password SECRET");
    out.flush();
    CountDownLatch stop = new CountDownLatch(1);
    Thread hook = new Thread(stop::countDown, "guiserver-shutdown");
    Runtime.getRuntime().addShutdownHook(hook);
    long start = System.nanoTime();
    long end = seconds > 0 ? start + TimeUnit.SECONDS.toNanos(seconds) : Long.MAX_VALUE;
    try {
      // Wake for the next status line (every 10 s) or the end, whichever comes first.
      while (!stop.await(
          Math.min(TimeUnit.SECONDS.toNanos(10), end - System.nanoTime()), TimeUnit.NANOSECONDS)) {
        long s = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - start);
        ArServerModes modes = gui.getModes();
        out.printf(
            Locale.ROOT,
            "t=%4ds  clients %d  mode %s: %s  pose %s%s%n",
            s,
            server.getNumClients(),
            modes.getMode(),
            modes.getStatus(),
            robot.getPose(),
            forwarder == null ? "" : videoStatus(forwarder.getStats()));
        out.flush();
        if (System.nanoTime() >= end) {
          break;
        }
        if (!robot.isConnected()) {
          out.println("The robot disconnected: " + robot.getConnectFailure());
          return 1;
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      try {
        Runtime.getRuntime().removeShutdownHook(hook);
      } catch (IllegalStateException shuttingDown) {
        // Ctrl-C: the JVM is exiting; the servers close in the callers' finally blocks.
      }
    }
    return 0;
  }

  /** The forwarder's part of the status line. */
  static String videoStatus(ForwarderStats v) {
    return String.format(
        Locale.ROOT,
        "  video %s, %d frames, %d dropped",
        v.connected() ? "forwarded" : "not connected",
        v.frames(),
        v.dropped());
  }

  private static void pause(Duration d) {
    try {
      TimeUnit.NANOSECONDS.sleep(d.toNanos());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }
}
