package org.jaria.net.server;

import java.io.IOException;
import java.util.Locale;
import java.util.Objects;
import org.jaria.map.ArMap;
import org.jaria.net.provider.ConfigRegistry;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.provider.PathPlanningInfo;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.info.ArServerHandlerCamera;
import org.jaria.net.server.info.ArServerHandlerCommands;
import org.jaria.net.server.info.ArServerHandlerConfig;
import org.jaria.net.server.info.ArServerHandlerLocalization;
import org.jaria.net.server.info.ArServerHandlerMap;
import org.jaria.net.server.info.ArServerHandlerPopup;
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
import org.jaria.robot.ArRobot;

/**
 * The thesis's guiServer (§6.1) assembled: an {@link ArServerBase} with every service a monitor
 * uses — robot state, range readings, the map, information strings, custom commands, the four modes
 * (stop by default, teleoperation, wander, goto with {@code home}), relocalization, drawings and
 * popups — plus localization, path planning, configuration and video when their providers are
 * given. The data are registered in a fixed order (ARIA's recorded clients use their numbers); what
 * was added later comes last (see {@code aria-net/PROTOCOL.md} §8).
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
 * <p>{@code jaria demo guiserver} runs exactly this; {@code org.jaria.net.sim.SimulatedGuiServer}
 * (module {@code tools}) does it on an embedded simulator. The protocol is described in {@code
 * aria-net/PROTOCOL.md}.
 */
public final class GuiServer implements AutoCloseable {

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
    new ArServerHandlerLocalization(server, robot, b.localization, b.map);
    ArServerInfoPath pathInfo =
        b.pathPlanning != null ? new ArServerInfoPath(server, b.pathPlanning) : null;
    ArServerHandlerConfig configHandler =
        b.config != null ? new ArServerHandlerConfig(server, b.config) : null;
    if (b.video != null) {
      new ArServerHandlerCamera(server, b.video);
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
    new ArServerModeDock(server, b.map);
    mapHandler.addMapBinary();
    if (locInfo != null) {
      locInfo.addLocalizationSnapshot();
    }
    if (pathInfo != null) {
      pathInfo.addPathSnapshot();
    }
    GuiDrawings.addDrawings(drawings, robot, b.pathPlanning);
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

    /** An information table of your own (entries are added to it). */
    public Builder infoGroup(ArStringInfoGroup g) {
      infoGroup = g;
      return this;
    }

    /** The server, with its services registered, not yet open. */
    public GuiServer build() {
      return new GuiServer(this);
    }
  }
}
