package org.jaria.tools.web;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.server.Authenticator;
import org.jaria.net.server.ServerOptions;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.jaria.web.server.WebOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jaria web}: a simulated robot that localizes with its sonar and plans paths, shown in a
 * web browser (and to Foxglove or Lichtblick over the same port). With {@code --allow-control} the
 * page drives it with the arrow keys, sends it to where you click, and pauses, steps or speeds up
 * the simulation.
 */
@Command(
    name = "web",
    sortOptions = false,
    description = {
      "Watch (and with --allow-control drive) a simulated robot in a web browser: the map, the"
          + " robot's true and believed pose, particles, sonar, laser and planned path.",
      "The same port speaks Foxglove's WebSocket protocol. Runs until Ctrl-C (or --seconds)."
    })
public final class WebCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(
      names = "--map",
      paramLabel = "FILE",
      description = "A .map file or a bundled map (office, hall). Default: ${DEFAULT-VALUE}.")
  String map = "office";

  @Option(names = "--robot", description = "Robot model (default ${DEFAULT-VALUE}).")
  String model = "p3dx-sh";

  @Option(
      names = "--port",
      description =
          "TCP port of the page and the WebSocket (default ${DEFAULT-VALUE}; 0: any free one).")
  int port = WebOptions.DEFAULT_PORT;

  @Option(
      names = "--bind",
      paramLabel = "ADDRESS",
      description =
          "Address to listen on (default ${DEFAULT-VALUE}: this computer only; any other address"
              + " gets a secret token in the printed URL).")
  String bind = "127.0.0.1";

  @Option(
      names = "--allow-control",
      description =
          "Viewers may drive (arrow keys), send goals (click) and pause, step or speed up the"
              + " simulation. Without it the page only watches.")
  boolean allowControl;

  @Option(
      names = "--record",
      paramLabel = "FILE.mcap",
      description = "Also record every channel to an MCAP file (Foxglove and Lichtblick open it).")
  Path record;

  @Option(names = "--speed", paramLabel = "X", description = "Simulation speed-up (default 1).")
  double speed = 1;

  @Option(names = "--seed", description = "Simulator and localization seed (default 1).")
  long seed = 1;

  @Option(
      names = "--seconds",
      description = "Stop after this many seconds (default ${DEFAULT-VALUE}: run until Ctrl-C).")
  int seconds;

  private final CountDownLatch stop = new CountDownLatch(1);

  /** Told of the running simulation and web view (tests watch the world through it). */
  java.util.function.BiConsumer<SimulatedGuiServer, WebView> onStarted = (s, v) -> {};

  @Override
  public Integer call() {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    try {
      if (!(speed > 0 && speed <= 50)) {
        throw new IllegalArgumentException("--speed is above 0 and at most 50, not " + speed);
      }
      ArMap m = loadMap(map);
      String mapName = Path.of(map).getFileName().toString();
      WebOptions options =
          WebOptions.loopback(port)
              .withBind(bind)
              .withControl(allowControl)
              .withName("jaria web · " + mapName);
      ServerOptions monitors =
          ServerOptions.builder()
              .serverName("guiServer")
              .port(0)
              .bindAddress("127.0.0.1")
              .authenticator(Authenticator.open())
              .build();
      try (SimulatedGuiServer s =
          SimulatedGuiServer.start(
              new SimulatedGuiServer.Options(
                  m, mapName, model, seed, monitors, ArnlNavigation.Mode.THREADED, speed, false))) {
        // The p3dx-sh carries a laser: switch the simulated one on, so the page shows its scans.
        var robot = s.robot();
        robot.lock();
        try {
          robot.addRangeDevice(new org.jaria.range.ArSimulatedLaser());
        } finally {
          robot.unlock();
        }
        NavigationView nv =
            NavigationView.simulated(
                s.world(), s.sim().sim().getName(), s.nav(), m, mapName, speed);
        out.printf(
            Locale.ROOT,
            "Simulator: a %s on %s, %s; localized at home: %s%n",
            model,
            mapName,
            speed == 1 ? "real time" : speed + " x real time",
            s.wasLocalized() ? "yes" : "no");
        try (WebView v =
            WebView.start(options, nv.source(), nv.controls(), record, true, out, nv.driver())) {
          out.println(
              seconds > 0 ? "Stops after " + seconds + " s; Ctrl-C sooner." : "Ctrl-C stops.");
          out.flush();
          onStarted.accept(s, v);
          waitForStop();
          out.printf(Locale.ROOT, "Web view: %s%n", summary(v));
        }
      }
      return 0;
    } catch (IllegalArgumentException | IOException e) {
      err.println("jaria web: " + e.getMessage());
      err.flush();
      return 2;
    }
  }

  private static String summary(WebView v) {
    var s = v.server().stats();
    return String.format(
        Locale.ROOT,
        "%d viewer(s), %d messages sent, %d dropped, %d control commands",
        s.clientsServed(),
        s.messagesSent(),
        s.messagesDropped(),
        s.controlCommands());
  }

  private void waitForStop() {
    Thread hook = new Thread(stop::countDown, "web-shutdown");
    Runtime.getRuntime().addShutdownHook(hook);
    try {
      if (seconds > 0) {
        stop.await(seconds, TimeUnit.SECONDS);
      } else {
        stop.await();
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } finally {
      try {
        Runtime.getRuntime().removeShutdownHook(hook);
      } catch (IllegalStateException shuttingDown) {
        // Ctrl-C: the JVM is exiting; the servers close in the try-with-resources above.
      }
    }
  }

  /** Asks a running {@link #call()} to stop (as Ctrl-C does). */
  public void requestStop() {
    stop.countDown();
  }

  static ArMap loadMap(String map) throws IOException {
    try {
      return ArMap.load(map);
    } catch (MapFormatException e) {
      throw new IllegalArgumentException("not a valid map: " + e.getMessage(), e);
    }
  }
}
