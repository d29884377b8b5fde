package org.jaria.apps.monitor;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Function;
import org.jaria.apps.fx.PointLayer;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;
import org.jaria.map.MapFormatException;
import org.jaria.net.ArNetPacket;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.client.ArNetPacketArgs;
import org.jaria.net.client.ClientOptions;
import org.jaria.net.client.ConnectionListener;
import org.jaria.net.data.CommandInfo;
import org.jaria.net.data.ConfigLayout;
import org.jaria.net.data.InfoStrings;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.MapBinaryLayout;
import org.jaria.net.data.MapData;
import org.jaria.net.data.Particles;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.PhysicalInfo;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.data.SensorReadings;
import org.jaria.net.data.VideoFrame;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The monitor's connection to a guiServer: subscribes to what the window draws, stores the values
 * in a {@link MonitorState}, and sends the operator's commands. Every method may be called from any
 * thread; none waits for the network except {@link #connect} (run it off the JavaFX thread).
 */
final class GuiServerLink implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(GuiServerLink.class);

  /** Subscription intervals, ms: the robot smoothly, the slow things slowly. */
  static final long FAST_MS = 100;

  static final long MEDIUM_MS = 250;
  static final long SLOW_MS = 1000;

  private final ArClientBase client = new ArClientBase(ClientOptions.defaults("jaria-monitor"));
  private final MonitorState state;
  // The labels of getStrings's values, from getStringsInfo (asked once per connection).
  private volatile List<String> stringLabels = List.of();
  private final Runnable changed;
  private final LinkExtras extras;

  /**
   * A link storing into {@code state} and calling {@code changed} (on the reader thread) after
   * every update.
   */
  GuiServerLink(MonitorState state, Runnable changed) {
    this.state = state;
    this.changed = changed;
    on("update", RobotUpdate::read, v -> state.robot = v);
    on("getSensorCurrent", SensorReadings::read, v -> state.sensors = v);
    on("getLocalizationSnapshot", LocalizationSnapshot::read, v -> state.localization = v);
    on("getLocPoints", Particles::read, v -> state.particles = v);
    on("getPathSnapshot", PathSnapshot::read, v -> state.path = v);
    extras = new LinkExtras(client, state, changed);
    // Another client changed the configuration (ArNetworking's configUpdated): read it again.
    client.addHandler("configUpdated", p -> fetchConfig());
    on("getStrings", p -> InfoStrings.read(p, stringLabels), v -> state.strings = v);
    on("getVideo", VideoFrame::read, v -> state.video = v);
    client.addHandler(
        "mapUpdated",
        p -> {
          // ArNetworking's signal that the map changed: fetch it again.
          mapVersion.incrementAndGet();
          fetchMap();
        });
  }

  private final java.util.concurrent.atomic.AtomicLong mapVersion =
      new java.util.concurrent.atomic.AtomicLong(1);

  /** Data whose packets the monitor could not read: asked for no more (logged once). */
  private final java.util.Set<String> unreadable =
      java.util.concurrent.ConcurrentHashMap.newKeySet();

  /**
   * Asks for the configuration once (ArNetworking's getConfigBySections answers once, one packet
   * per section); the monitor asks again after it changed the configuration.
   */
  void fetchConfig() {
    if (!client.dataExists("getConfigBySections")) {
      return;
    }
    CompletableFuture<?> unused =
        request("getConfigBySections")
            .thenAccept(
                p -> {
                  state.config = ConfigLayout.readAll(p);
                  changed.run();
                })
            .exceptionally(
                e -> {
                  log.info("the server's configuration could not be read: {}", e.getMessage());
                  return null;
                });
  }

  /**
   * Asks for the map's name and then the map: with getMapBinary (its points as numbers, smaller,
   * what MobileEyes uses) if the server has it, else with getMap (text).
   */
  private void fetchMap() {
    boolean binary = client.dataExists("getMapBinary");
    if (!binary && !client.dataExists("getMap")) {
      return;
    }
    CompletableFuture<?> unused =
        request("getMapName")
            .thenCompose(
                n ->
                    request(binary ? "getMapBinary" : "getMap")
                        .thenApply(m -> mapView(m, n.bufToStr(), binary)))
            .thenAccept(
                v -> {
                  state.map = v;
                  changed.run();
                })
            .exceptionally(
                e -> {
                  log.info("the server's map could not be read: {}", e.getMessage());
                  return null;
                });
  }

  private <T> void on(String name, Function<ArNetPacket, T> read, Consumer<T> store) {
    client.addHandler(
        name,
        p -> {
          T v;
          try {
            v = read.apply(p);
          } catch (RuntimeException e) {
            // An ArNetworking server may offer data of this name in a layout the monitor does not
            // read (ARIA's config, ARNL's path...): stop asking rather than fail ten times a
            // second.
            if (unreadable.add(name)) {
              log.info(
                  "{} from this server is not in a layout the monitor reads: {}",
                  name,
                  e.getMessage());
              client.requestStop(name);
            }
            return;
          }
          store.accept(v);
          changed.run();
        });
  }

  private MonitorState.MapView mapView(ArNetPacket p, String name, boolean binary) {
    MapData d =
        binary
            ? new MapData(name, mapVersion.get(), MapBinaryLayout.readText(p))
            : MapData.read(p, name, mapVersion.get());
    try {
      ArMap m = d.toArMap();
      ArMapPoints pts = m.getPoints();
      return new MonitorState.MapView(
          d.name(), d.version(), m, new PointLayer(pts.xArray(), pts.yArray()));
    } catch (MapFormatException e) {
      log.warn("the server's map {} does not parse: {}", d.name(), e.getMessage());
      return null;
    }
  }

  /** Hears the connection come and go (on the client's threads). */
  void addConnectionListener(ConnectionListener l) {
    client.addConnectionListener(l);
  }

  /**
   * Connects, logs in and subscribes; then asks once for what does not change.
   *
   * @throws ArClientException if the server is not there or refuses the login
   */
  void connect(String host, int port, String user, String password) throws ArClientException {
    state.clear();
    unreadable.clear();
    subscribe("update", FAST_MS);
    for (String d : List.of("getLocPoints", "getStrings")) {
      subscribe(d, MEDIUM_MS);
    }
    client.connect(host, port, user == null ? "" : user, password);
    extras.connected(MEDIUM_MS);
    if (client.dataExists("getSensorCurrent")) {
      // ArNetworking sends one named sensor's readings per request.
      CompletableFuture<Duration> unused =
          client.request("getSensorCurrent", FAST_MS, ArNetPacketArgs.of("sonar"));
    }
    fetchConfig();
    if (client.dataExists("configUpdated")) {
      subscribe("configUpdated", -1);
    }
    if (client.dataExists("mapUpdated")) {
      subscribe("mapUpdated", -1);
    }
    fetchMap();
    if (client.dataExists("getStringsInfo")) {
      CompletableFuture<?> unused =
          request("getStringsInfo")
              .thenAccept(
                  p -> {
                    stringLabels = InfoStrings.readLabels(p);
                    // Values that came before their labels: label them now.
                    InfoStrings early = state.strings;
                    if (early != null) {
                      state.strings = early.withLabels(stringLabels);
                    }
                  });
    }
    if (client.dataExists("physicalInfo")) {
      CompletableFuture<?> unused =
          request("physicalInfo").thenAccept(p -> state.physical = PhysicalInfo.read(p));
    }
    if (client.dataExists("getGoals")) {
      CompletableFuture<?> unused =
          request("getGoals")
              .thenAccept(
                  p -> {
                    // ArNetworking's layout: one string per goal, to the end.
                    List<String> g = new java.util.ArrayList<>();
                    while (p.hasMore()) {
                      g.add(p.bufToStr());
                    }
                    state.goals = List.copyOf(g);
                    changed.run();
                  });
    }
  }

  private void subscribe(String name, long ms) {
    CompletableFuture<?> unused =
        client
            .request(name, ms)
            .exceptionally(
                e -> {
                  // Data this server does not offer (no camera, no planner): nothing to draw.
                  log.debug("no subscription to {}: {}", name, e.getMessage());
                  return null;
                });
  }

  /** Starts or stops receiving video. */
  void watchVideo(boolean on) {
    if (on && client.dataExists("getVideo")) {
      subscribe("getVideo", 200);
    } else {
      client.requestStop("getVideo");
      state.video = null;
    }
  }

  /** Sends a request or command; the future fails with the server's message. */
  CompletableFuture<ArNetPacket> request(String name, Object... args) {
    return client.requestOnce(name, args);
  }

  /** Answers popup {@code id} with button {@code button} (ArNetworking's popupClicked). */
  CompletableFuture<?> popupClicked(int id, int button) {
    return extras.popupClicked(id, button);
  }

  /** The custom commands the server offers. */
  CompletableFuture<List<CommandInfo>> commands() {
    if (!client.dataExists("listCommands")) {
      return CompletableFuture.completedFuture(List.of());
    }
    CompletableFuture<List<CommandInfo>> simple =
        request("listCommands").thenApply(p -> CommandInfo.readList(p, false));
    if (!client.dataExists("listStringCommands")) {
      return simple;
    }
    return simple.thenCombine(
        request("listStringCommands").thenApply(p -> CommandInfo.readList(p, true)),
        (a, b) -> java.util.stream.Stream.concat(a.stream(), b.stream()).toList());
  }

  /** Whether the server offers data of this name to this user. */
  boolean offers(String name) {
    return client.dataExists(name);
  }

  boolean isConnected() {
    return client.isConnected();
  }

  String getLastError() {
    return client.getLastError();
  }

  /** Disconnects (subscriptions are kept for the next connection). */
  void disconnect() {
    client.disconnect();
  }

  @Override
  public void close() {
    client.close();
  }
}
