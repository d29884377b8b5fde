package org.jaria.net.guiserver;

import java.io.IOException;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;
import org.jaria.net.provider.ConfigRegistry;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.CallPolicy;
import org.jaria.net.server.MapFolder;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.info.ArCameraCollection;
import org.jaria.net.server.info.ArServerHandlerCamera;
import org.jaria.net.server.info.ArServerHandlerCameraCollection;
import org.jaria.net.server.info.ArServerHandlerCommands;
import org.jaria.net.server.info.ArServerHandlerConfig;
import org.jaria.net.server.info.ArServerHandlerLocalization;
import org.jaria.net.server.info.ArServerHandlerMap;
import org.jaria.net.server.info.ArServerHandlerPopup;
import org.jaria.net.server.info.ArServerHandlerVideo;
import org.jaria.net.server.info.ArServerInfoDrawings;
import org.jaria.net.server.info.ArServerInfoLocalization;
import org.jaria.net.server.info.ArServerInfoPath;
import org.jaria.net.server.info.ArServerInfoRobot;
import org.jaria.net.server.info.ArServerInfoSensor;
import org.jaria.net.server.info.ArServerInfoStrings;
import org.jaria.net.server.info.ArStringInfoGroup;
import org.jaria.net.server.modes.ArServerModeDock;
import org.jaria.net.server.modes.ArServerModeGoto;
import org.jaria.net.server.modes.ArServerModeRatioDrive;
import org.jaria.net.server.modes.ArServerModeStop;
import org.jaria.net.server.modes.ArServerModeWander;
import org.jaria.net.server.modes.ArServerModes;
import org.jaria.ptz.ArPTZ;
import org.jaria.robot.ArRobot;

/**
 * The thesis's guiServer (§6.1) assembled: an {@link ArServerBase} with every service a monitor
 * uses — robot state, range readings, the map, information strings, custom commands, the four modes
 * (stop by default, teleoperation, wander, goto with {@code home}), relocalization, drawings and
 * popups — plus localization, path planning, configuration, video and a pan-tilt-zoom camera when
 * their providers are given. The data are registered in a fixed order (ARIA's recorded clients use
 * their numbers); what was added later comes last (see {@code aria-net/PROTOCOL.md} §8).
 *
 * <pre>{@code
 * ArnlNavigation nav = ArnlNavigation.create(robot, map, ArnlNavigation.Mode.THREADED, 1);
 * nav.localizeAtHome();
 * try (GuiServer gui = GuiServer.builder(robot)
 *         .options(ServerOptions.builder().port(7272).authenticator(users).build())
 *         .map(map, "office.map")
 *         .localization(nav.localization())
 *         .pathPlanning(nav.pathPlanning())
 *         .config(nav.configRegistry())
 *         .build()) {
 *   gui.open();
 *   robot.waitForRunExit();
 * }
 * }</pre>
 *
 * <p>{@code jaria demo guiserver} runs exactly this; {@code
 * org.jaria.simguiserver.SimulatedGuiServer} (module {@code sim-guiserver}) does it on an embedded
 * simulator. The protocol is described in {@code aria-net/PROTOCOL.md}.
 */
public final class GuiServer implements AutoCloseable {

  private static final org.slf4j.Logger log = org.slf4j.LoggerFactory.getLogger(GuiServer.class);

  private final ArServerBase server;
  private final ArServerInfoRobot robotInfo;
  private final ArServerHandlerCommands commands;
  private final ArStringInfoGroup infoGroup;
  private final ArServerHandlerMap mapHandler;
  private final ArServerModeStop modeStop;
  private final ArServerModeRatioDrive modeRatioDrive;
  private final ArServerModeWander modeWander;
  private final ArServerModeGoto modeGoto;
  private final ArServerInfoDrawings drawings;
  private final ArServerHandlerPopup popups;
  private final ArServerHandlerCamera camera;
  private final ArServerHandlerLocalization locHandler;
  private final ArServerModeDock dock;
  private final MapFolder mapFolder;
  private final Consumer<ArMap> mapChanged;
  private volatile String mapName;

  private GuiServer(Builder b) {
    ArRobot robot = b.robot;
    server = new ArServerBase(b.options, robot);
    robotInfo = new ArServerInfoRobot(server, robot);
    new ArServerInfoSensor(server, robot);
    mapHandler = new ArServerHandlerMap(server, b.map, b.mapName);
    infoGroup = b.infoGroup != null ? b.infoGroup : new ArStringInfoGroup();
    infoGroup.addStringDouble("Robot cycle (ms)", 8, () -> robot.getLastCycleNanos() / 1e6, "%.2f");
    infoGroup.addStringInt("Network clients", 4, server::getNumClients);
    ArServerInfoLocalization locInfo = null;
    if (b.localization != null) {
      LocalizationInfo loc = b.localization;
      infoGroup.addStringDouble(
          "Localization score", 8, () -> loc.getLocalizationState().score(), "%.3f");
      locInfo = new ArServerInfoLocalization(server, loc);
    }
    ArServerInfoStrings strings = new ArServerInfoStrings(server, infoGroup);
    locHandler = new ArServerHandlerLocalization(server, robot, b.localization, b.map);
    ArServerInfoPath pathInfo =
        b.pathPlanning != null ? new ArServerInfoPath(server, b.pathPlanning) : null;
    mapFolder = b.mapFolder;
    mapChanged = b.mapChanged;
    mapName = b.mapName;
    // ARIA's Files/Map parameter in front of the program's own: changing it changes the map.
    ArServerHandlerConfig configHandler =
        b.config != null
            ? new ArServerHandlerConfig(
                server, new FilesConfig(b.config, () -> mapName, this::changeMapForClient))
            : null;
    if (b.video != null) {
      new ArServerHandlerVideo(server, b.video);
    }
    commands = new ArServerHandlerCommands(server);
    commands.addCommand("enableMotors", "switches the motors on", robot::enableMotors);
    commands.addCommand("disableMotors", "switches the motors off", robot::disableMotors);
    // Switching the motors off stops the robot: a safety command, like stop.
    server.setCallPolicy("disableMotors", CallPolicy.SAFETY);
    modeStop = new ArServerModeStop(server, robot);
    modeRatioDrive = new ArServerModeRatioDrive(server, robot);
    modeWander = new ArServerModeWander(server, robot);
    modeGoto = new ArServerModeGoto(server, robot, b.pathPlanning, b.map);
    modeStop.addAsDefaultMode();
    // Registered last so that the data numbers ARIA clients were recorded with stay the same.
    commands.addStringCommandList();
    strings.addStringsInfo();
    // Added after the services above (whose numbers ARIA's recorded clients used), in this order.
    drawings = new ArServerInfoDrawings(server);
    popups = new ArServerHandlerPopup(server, robot.getClock()::millis);
    if (configHandler != null) {
      configHandler.addDefaultServerCommands();
    }
    modeGoto.addHomeRequest();
    dock = new ArServerModeDock(server, b.map);
    mapHandler.addMapBinary();
    if (locInfo != null) {
      locInfo.addLocalizationSnapshot();
    }
    if (pathInfo != null) {
      pathInfo.addPathSnapshot();
    }
    GuiDrawings.addDrawings(drawings, robot, b.pathPlanning);
    if (b.ptz != null) {
      // As serverDemo names its VC-C4, listed for clients by ArServerHandlerCameraCollection.
      ArCameraCollection cameras = new ArCameraCollection();
      String type = b.ptz.getTypeName().toUpperCase(Locale.ROOT);
      cameras.addCamera(CAMERA_NAME, type, "Camera", type);
      new ArServerHandlerCameraCollection(server, cameras);
      camera = new ArServerHandlerCamera(CAMERA_NAME, server, robot, b.ptz, cameras);
    } else {
      camera = null;
    }
  }

  /** The name of the pan-tilt-zoom camera, the suffix of its requests ("setCameraAbsCam1"). */
  public static final String CAMERA_NAME = "Cam1";

  /**
   * Serves another map (what a client does by setting ARIA's {@code Files/Map} parameter): stops
   * the robot, hands the map to the navigation (see {@link Builder#mapChange}), then to the goto,
   * dock and relocalization requests, and serves it to clients, who are told with {@code
   * mapUpdated}. Call it from any thread but the robot's cycle, which it waits for.
   *
   * @param name the map's name for clients (its file name)
   * @throws IllegalStateException if the robot's cycle does not stop the robot within 5 s
   */
  public synchronized void setMap(ArMap map, String name) {
    CompletableFuture<Void> stopped = new CompletableFuture<>();
    if (!server.runOnCycle(
        () -> {
          modeStop.activate();
          stopped.complete(null);
        })) {
      throw new IllegalStateException("the robot's command queue is full; try again in a moment");
    }
    try {
      stopped.get(5, TimeUnit.SECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IllegalStateException("interrupted while stopping the robot for a new map", e);
    } catch (ExecutionException | TimeoutException e) {
      throw new IllegalStateException(
          "the robot's cycle did not stop the robot within 5 s: is the robot running?", e);
    }
    if (mapChanged != null) {
      mapChanged.accept(map);
    }
    modeGoto.setMap(map);
    dock.setMap(map);
    locHandler.setMap(map);
    mapName = name;
    mapHandler.setMap(map, name);
  }

  /** The name of the map served. */
  public String getMapName() {
    return mapName;
  }

  /** A client set Files/Map: loads the map from the map folder; null, or why not. */
  private String changeMapForClient(String name) {
    ArMap m;
    try {
      m = mapFolder.load(name);
    } catch (IllegalArgumentException e) {
      return "Map: " + e.getMessage();
    } catch (IOException | MapFormatException e) {
      log.warn("a client asked for map '{}', which could not be read: {}", name, e.getMessage());
      return "Map: '" + name + "' could not be read as a map (the server's log says why)";
    }
    try {
      setMap(m, name);
    } catch (IllegalStateException e) {
      return "Map: " + e.getMessage();
    }
    log.info("a client changed the map to '{}'", name);
    return null;
  }

  /** A builder for a guiServer driving {@code robot}. */
  public static Builder builder(ArRobot robot) {
    return new Builder(robot);
  }

  /**
   * Starts serving.
   *
   * @throws IOException if the port cannot be opened
   */
  public void open() throws IOException {
    server.open();
  }

  /** Stops serving (the robot is left as it is). */
  @Override
  public void close() {
    server.close();
  }

  /** The server, to add data of your own. */
  public ArServerBase getServer() {
    return server;
  }

  /** The robot-state service. */
  public ArServerInfoRobot getRobotInfo() {
    return robotInfo;
  }

  /** The custom commands, to add your own. */
  public ArServerHandlerCommands getCommands() {
    return commands;
  }

  /** The information table, to add your own values. */
  public ArStringInfoGroup getInfoGroup() {
    return infoGroup;
  }

  /** The drawings clients may draw on the map, to add your own. */
  public ArServerInfoDrawings getDrawings() {
    return drawings;
  }

  /** The popups, to show one on every client. */
  public ArServerHandlerPopup getPopups() {
    return popups;
  }

  /** The map service (to serve a new map). */
  public ArServerHandlerMap getMapHandler() {
    return mapHandler;
  }

  /** The pan-tilt-zoom camera's handler, or null if the server was given none. */
  public ArServerHandlerCamera getCameraHandler() {
    return camera;
  }

  /** The server's modes. */
  public ArServerModes getModes() {
    return ArServerModes.of(server);
  }

  /** The stop mode (the default). */
  public ArServerModeStop getModeStop() {
    return modeStop;
  }

  /** The teleoperation mode. */
  public ArServerModeRatioDrive getModeRatioDrive() {
    return modeRatioDrive;
  }

  /** The wander mode. */
  public ArServerModeWander getModeWander() {
    return modeWander;
  }

  /** The goto mode. */
  public ArServerModeGoto getModeGoto() {
    return modeGoto;
  }

  @Override
  public String toString() {
    return String.format(
        Locale.ROOT,
        "GuiServer[%s, %d clients]",
        server.isOpen() ? "port " + server.getPort() : "closed",
        server.getNumClients());
  }

  /** Builds a {@link GuiServer}. Only the robot is required. */
  public static final class Builder {
    private final ArRobot robot;
    private ServerOptions options = ServerOptions.defaults();
    private ArMap map;
    private String mapName = "";
    private LocalizationInfo localization;
    private PathPlanningInfo pathPlanning;
    private ConfigRegistry config;
    private VideoSource video;
    private ArPTZ ptz;
    private MapFolder mapFolder;
    private Consumer<ArMap> mapChanged;
    private ArStringInfoGroup infoGroup;

    private Builder(ArRobot robot) {
      this.robot = Objects.requireNonNull(robot, "a guiServer needs a robot");
    }

    /** Port, authentication and limits. */
    public Builder options(ServerOptions o) {
      options = o;
      return this;
    }

    /** The map to serve (and whose goals "gotoGoal" knows). */
    public Builder map(ArMap m, String name) {
      map = m;
      mapName = name;
      return this;
    }

    /**
     * Where the maps come from that clients may switch to with ARIA's {@code Files/Map}
     * configuration parameter (offered with the configuration, see {@link #config}): the bundled
     * maps by default, which {@code folder} adds to; and {@code navigation} (may be null), told of
     * the new map before it is served ({@code nav::setMap} for an {@code ArnlNavigation}).
     */
    public Builder mapChange(MapFolder folder, Consumer<ArMap> navigation) {
      mapFolder = folder;
      mapChanged = navigation;
      return this;
    }

    /** The localizer. */
    public Builder localization(LocalizationInfo l) {
      localization = l;
      return this;
    }

    /** The path planner (goto then plans instead of driving straight). */
    public Builder pathPlanning(PathPlanningInfo p) {
      pathPlanning = p;
      return this;
    }

    /** The configuration. */
    public Builder config(ConfigRegistry c) {
      config = c;
      return this;
    }

    /** A camera. */
    public Builder video(VideoSource v) {
      video = v;
      return this;
    }

    /**
     * A pan-tilt-zoom camera (a VC-C4 on the robot's AUX port, say) that clients may point: served
     * as camera "Cam1" with ArNetworking's camera requests and listed by {@code getCameraList}.
     */
    public Builder ptz(ArPTZ p) {
      ptz = p;
      return this;
    }

    /** An information table of your own (entries are added to it). */
    public Builder infoGroup(ArStringInfoGroup g) {
      infoGroup = g;
      return this;
    }

    /** The server, with its services registered, not yet open. */
    public GuiServer build() {
      if (mapFolder == null) {
        try {
          mapFolder = new MapFolder(null);
        } catch (IOException e) {
          throw new IllegalStateException("bundled maps need no folder", e);
        }
      }
      return new GuiServer(this);
    }
  }
}
