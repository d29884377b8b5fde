package org.jaria.net.arnl;

import java.util.Objects;
import org.jaria.arnl.ArActionLost;
import org.jaria.arnl.ArActionSlowDownWhenNotCertain;
import org.jaria.arnl.ArForbiddenRangeDevice;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.config.ArConfig;
import org.jaria.map.ArMap;
import org.jaria.net.provider.ArConfigRegistry;
import org.jaria.net.server.Where;
import org.jaria.net.server.info.ArServerHandlerCommands;
import org.jaria.range.ArBumpers;
import org.jaria.range.ArIRs;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/**
 * A robot set up for navigation as in the thesis's guiServer (§6.1): sonar, bumpers, IRs (when the
 * robot has them) and the map's forbidden lines as range devices; SonARNL sonar localization; path
 * planning with the lost and slow-down-when-uncertain actions; all parameters in one {@link
 * ArConfig} that monitors can edit. Hand {@link #localization()}, {@link #pathPlanning()} and
 * {@link #configRegistry()} to a {@link org.jaria.net.server.GuiServer}.
 *
 * <pre>{@code
 * try (ArnlNavigation nav = ArnlNavigation.create(robot, map, ArnlNavigation.Mode.THREADED, 1)) {
 *   nav.localizeAtHome();
 *   GuiServer gui = GuiServer.builder(robot).map(map, "office.map")
 *       .localization(nav.localization()).pathPlanning(nav.pathPlanning())
 *       .config(nav.configRegistry()).build();
 *   ...
 * }
 * }</pre>
 */
public final class ArnlNavigation implements AutoCloseable {

  /** Where localization updates and plans are computed. */
  public enum Mode {
    /** On their own threads: real robots and simulators running in real time. */
    THREADED,
    /** Inside the robot's cycle (and the caller for a new goal): lockstep simulations. */
    SYNCHRONOUS
  }

  private final ArRobot robot;
  private final ArConfig config;
  private final ArSonarLocalizationTask loc;
  private final ArPathPlanningTask path;
  private final ArnlLocalization locInfo;
  private final ArnlPathPlanning pathInfo;
  private final ArConfigRegistry registry;

  private ArnlNavigation(
      ArRobot robot, ArConfig config, ArSonarLocalizationTask loc, ArPathPlanningTask path) {
    this.robot = robot;
    this.config = config;
    this.loc = loc;
    this.path = path;
    this.locInfo = new ArnlLocalization(loc);
    this.pathInfo = new ArnlPathPlanning(path);
    this.registry = new ArConfigRegistry(config);
  }

  /**
   * Adds the range devices, localization and path planning to {@code robot} (connected or not).
   *
   * @param seed seed of the localization's random numbers
   */
  public static ArnlNavigation create(ArRobot robot, ArMap map, Mode mode, long seed) {
    Objects.requireNonNull(robot, "robot");
    Objects.requireNonNull(map, "a navigation server needs a map");
    ArSonarDevice sonar = new ArSonarDevice();
    ArBumpers bumpers = new ArBumpers();
    ArForbiddenRangeDevice forbidden = new ArForbiddenRangeDevice(map);
    robot.lock();
    try {
      robot.addRangeDevice(sonar);
      robot.addRangeDevice(bumpers);
      robot.addRangeDevice(forbidden);
    } finally {
      robot.unlock();
    }
    ArConfig config = new ArConfig();
    ArSonarLocalizationTask loc =
        ArSonarLocalizationTask.builder(robot, map)
            .sonar(sonar)
            .config(config)
            .mode(
                mode == Mode.THREADED
                    ? ArSonarLocalizationTask.UpdateMode.THREADED
                    : ArSonarLocalizationTask.UpdateMode.SYNCHRONOUS)
            .seed(seed)
            .build();
    ArPathPlanningTask path =
        ArPathPlanningTask.builder(robot, map)
            .sonar(sonar)
            .config(config)
            .mode(
                mode == Mode.THREADED
                    ? ArPathPlanningTask.PlanMode.THREADED
                    : ArPathPlanningTask.PlanMode.SYNCHRONOUS)
            .build();
    path.addRangeDevice(bumpers, ArPathPlanningTask.RangeType.CURRENT);
    path.addRangeDevice(forbidden, ArPathPlanningTask.RangeType.CURRENT);
    if (robot.getRobotParams().getNumIR() > 0) {
      ArIRs irs = new ArIRs();
      robot.addRangeDevice(irs);
      path.addRangeDevice(irs, ArPathPlanningTask.RangeType.CURRENT);
    }
    path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
    path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
    // Until a goal is given the robot stands still under the server's stop mode.
    path.getPathPlanActionGroup().deactivate();
    return new ArnlNavigation(robot, config, loc, path);
  }

  /**
   * Localizes at the map's home (needs sonar readings: let the robot run a moment first).
   *
   * @return whether the sonar confirmed the pose
   */
  public boolean localizeAtHome() {
    return loc.localizeRobotAtHomeBlocking();
  }

  /**
   * Adds the navigation's custom commands to a server: {@code localizeAtHome} (localizes at the
   * map's home again, replying whether the sonar confirmed it).
   */
  public void addCommands(ArServerHandlerCommands commands) {
    commands.addCommand(
        "localizeAtHome",
        "localizes the robot at the map's home again",
        "",
        Where.WORKER,
        args ->
            localizeAtHome()
                ? "localized at home"
                : "localized at home, but the sonar did not confirm it");
  }

  /** The localization for the server. */
  public ArnlLocalization localization() {
    return locInfo;
  }

  /** The path planning for the server's goto mode. */
  public ArnlPathPlanning pathPlanning() {
    return pathInfo;
  }

  /** The parameters of localization and path planning, for the server's configuration editor. */
  public ArConfigRegistry configRegistry() {
    return registry;
  }

  /** The parameters. */
  public ArConfig getConfig() {
    return config;
  }

  /** The localization task. */
  public ArSonarLocalizationTask getLocalizationTask() {
    return loc;
  }

  /** The path planning task. */
  public ArPathPlanningTask getPathPlanningTask() {
    return path;
  }

  /** The robot. */
  public ArRobot getRobot() {
    return robot;
  }

  /** Stops path planning and localization (the robot stays connected). */
  @Override
  public void close() {
    path.close();
    loc.close();
  }
}
