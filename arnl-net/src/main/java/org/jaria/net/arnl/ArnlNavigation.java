package org.jaria.net.arnl;

import java.util.List;
import java.util.Objects;
import org.jaria.arnl.ArActionLost;
import org.jaria.arnl.ArActionSlowDownWhenNotCertain;
import org.jaria.arnl.ArForbiddenRangeDevice;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.config.ArConfig;
import org.jaria.config.ArConfigArg;
import org.jaria.config.ArConfigSection;
import org.jaria.map.ArMap;
import org.jaria.net.data.ConfigSection;
import org.jaria.net.provider.ArConfigRegistry;
import org.jaria.net.provider.ConfigRegistry;
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
 * {@link #configRegistry()} to a {@link org.jaria.net.guiserver.GuiServer}.
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

  /** What is built on one map: the parameters, the two tasks and the map's forbidden lines. */
  private record Tasks(
      ArConfig config,
      ArSonarLocalizationTask loc,
      ArPathPlanningTask path,
      ArForbiddenRangeDevice forbidden) {}

  private final ArRobot robot;
  private final ArSonarDevice sonar;
  private final ArBumpers bumpers;
  private final ArIRs irs;
  private final Mode mode;
  private final long seed;
  private final ArnlLocalization locInfo;
  private final ArnlPathPlanning pathInfo;
  private final ConfigRegistry registry;
  private volatile Tasks tasks;

  private ArnlNavigation(
      ArRobot robot, ArSonarDevice sonar, ArBumpers bumpers, ArIRs irs, Mode mode, long seed) {
    this.robot = robot;
    this.sonar = sonar;
    this.bumpers = bumpers;
    this.irs = irs;
    this.mode = mode;
    this.seed = seed;
    this.locInfo = new ArnlLocalization(() -> tasks.loc());
    this.pathInfo = new ArnlPathPlanning(() -> tasks.path());
    this.registry =
        new ConfigRegistry() {
          @Override
          public List<ConfigSection> getSections() {
            return new ArConfigRegistry(tasks.config()).getSections();
          }

          @Override
          public String setParam(String section, String name, String valueText) {
            return new ArConfigRegistry(tasks.config()).setParam(section, name, valueText);
          }
        };
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
    ArIRs irs = robot.getRobotParams().getNumIR() > 0 ? new ArIRs() : null;
    robot.lock();
    try {
      robot.addRangeDevice(sonar);
      robot.addRangeDevice(bumpers);
      if (irs != null) {
        robot.addRangeDevice(irs);
      }
    } finally {
      robot.unlock();
    }
    ArnlNavigation nav = new ArnlNavigation(robot, sonar, bumpers, irs, mode, seed);
    nav.tasks = nav.build(map, null);
    return nav;
  }

  /** Localization and path planning on {@code map}, with the values of {@code previous} if any. */
  private Tasks build(ArMap map, ArConfig previous) {
    ArForbiddenRangeDevice forbidden = new ArForbiddenRangeDevice(map);
    robot.lock();
    try {
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
    if (irs != null) {
      path.addRangeDevice(irs, ArPathPlanningTask.RangeType.CURRENT);
    }
    path.getPathPlanActionGroup().addAction(new ArActionSlowDownWhenNotCertain(loc), 140);
    path.getPathPlanActionGroup().addAction(new ArActionLost(loc, path), 150);
    // Until a goal is given the robot stands still under the server's stop mode.
    path.getPathPlanActionGroup().deactivate();
    if (previous != null) {
      // What monitors set on the old map still holds on the new one.
      for (ArConfigSection s : previous.getSections()) {
        for (ArConfigArg a : s.getParams()) {
          config
              .findParam(s.getName(), a.getName())
              .ifPresent(n -> n.setValueFromText(a.getValueText()));
        }
      }
      config.callProcessFileCallBacks();
    }
    return new Tasks(config, loc, path, forbidden);
  }

  /**
   * Navigates on another map (ARIA's {@code Files/Map} parameter, set by a client): the plan in
   * progress is cancelled, localization and path planning start again on {@code map} with the
   * parameters as they were, and the robot is localized at the new map's home. Stop the robot first
   * (the guiServer does).
   *
   * @return whether the sonar confirmed the pose at the new map's home
   */
  public synchronized boolean setMap(ArMap map) {
    Objects.requireNonNull(map, "map");
    Tasks old = tasks;
    old.path().close();
    old.loc().close();
    robot.lock();
    try {
      robot.remRangeDevice(old.forbidden());
    } finally {
      robot.unlock();
    }
    tasks = build(map, old.config());
    return localizeAtHome();
  }

  /** The map navigated on. */
  public ArMap getMap() {
    return tasks.path().getAriaMap();
  }

  /**
   * Localizes at the map's home (needs sonar readings: let the robot run a moment first).
   *
   * @return whether the sonar confirmed the pose
   */
  public boolean localizeAtHome() {
    return tasks.loc().localizeRobotAtHomeBlocking();
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

  /**
   * The parameters of localization and path planning, for the server's configuration editor (those
   * of the current map's tasks).
   */
  public ConfigRegistry configRegistry() {
    return registry;
  }

  /** The parameters (of the current map's tasks). */
  public ArConfig getConfig() {
    return tasks.config();
  }

  /** The localization task (a new one after {@link #setMap}). */
  public ArSonarLocalizationTask getLocalizationTask() {
    return tasks.loc();
  }

  /** The path planning task (a new one after {@link #setMap}). */
  public ArPathPlanningTask getPathPlanningTask() {
    return tasks.path();
  }

  /** The robot. */
  public ArRobot getRobot() {
    return robot;
  }

  /** Stops path planning and localization (the robot stays connected). */
  @Override
  public synchronized void close() {
    Tasks t = tasks;
    t.path().close();
    t.loc().close();
  }
}
