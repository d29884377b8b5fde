package org.jaria.web.source;

import java.util.List;
import org.jaria.arnl.ArBaseLocalizationTask;
import org.jaria.arnl.ArPathPlanningTask;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.map.ArMap;
import org.jaria.params.ArRobotParams;
import org.jaria.range.ArSensorReading;
import org.jaria.robot.ArRobot;
import org.jaria.robot.RobotStatus;
import org.jaria.web.model.ClockFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.WorldFrame;

/**
 * A robot's own view of itself, from its software: the pose it believes (localization, else
 * odometry), the localization's particles, the planned path and goal, battery and speeds. Alone it
 * is the source for a real robot; as an {@link RobotOverlay} it adds these to the simulator's
 * picture of the same robot. Reads only snapshots ({@link ArRobot#getStatus()}, the particles'
 * copy, the path's copy), so it never holds the robot's lock.
 */
public final class NavigationSource implements FrameSource, RobotOverlay {

  /** Most particles sent per frame; more are thinned evenly. */
  public static final int MAX_PARTICLES = 5000;

  private final ArRobot robot;
  private final ArBaseLocalizationTask loc;
  private final ArPathPlanningTask path;
  private final RobotDriver driver;
  private final MapLayer map;

  /**
   * @param robot the robot
   * @param map its map (null: none)
   * @param mapName the map's name
   * @param loc its localization, or null
   * @param path its path planning, or null
   * @param driver the viewers' driver of it, or null (its mode shows "teleop" while it drives)
   */
  public NavigationSource(
      ArRobot robot,
      ArMap map,
      String mapName,
      ArBaseLocalizationTask loc,
      ArPathPlanningTask path,
      RobotDriver driver) {
    this.robot = robot;
    this.loc = loc;
    this.path = path;
    this.driver = driver;
    this.map = map == null ? MapLayer.EMPTY : MapLayers.of(map, mapName);
  }

  @Override
  public MapLayer map() {
    return map;
  }

  @Override
  public WorldFrame frame() {
    RobotStatus s = robot.getStatus();
    RobotFrame base =
        new RobotFrame(
            robot.getName(),
            robot.getRobotParams().getSubClassName(),
            null,
            s.pose(),
            outline(robot.getRobotParams(), s.pose()),
            sonarOrigins(s),
            sonarEchoes(s),
            null,
            Points.EMPTY,
            Points.EMPTY,
            null,
            new org.jaria.web.model.RobotStatus(0, 0, 0, false, false, "", Double.NaN));
    return new WorldFrame(ClockFrame.real(s.timeNanos()), List.of(apply(base)));
  }

  @Override
  public RobotFrame apply(RobotFrame base) {
    RobotStatus s = robot.getStatus();
    // The robot's pose is its odometry corrected by the localization's last fix: where it believes
    // it is now (the fix itself lags behind by the distance driven since).
    ArPose believed = s.pose();
    Points particles = Points.EMPTY;
    double score = Double.NaN;
    if (loc != null) {
      particles = particles(loc.getCurrentSamplePoses());
      score = loc.getLocalizationScore();
    }
    Points route = Points.EMPTY;
    ArPose goal = null;
    if (path != null && path.isActive()) {
      List<ArPose> poses = path.getCurrentPath();
      Points.Builder b = Points.builder(poses.size() + 1);
      b.add(believed.x(), believed.y());
      for (ArPose p : poses) {
        b.add(p.x(), p.y());
      }
      route = poses.isEmpty() ? Points.EMPTY : b.build();
      goal = path.getCurrentGoal();
    }
    boolean stalled = (s.stallValue() & 0x0101) != 0;
    double battery = s.realBatteryVoltage() > 0 ? s.realBatteryVoltage() : s.batteryVoltage();
    return base.withNavigation(
        believed,
        particles,
        route,
        goal,
        new org.jaria.web.model.RobotStatus(
            s.vel(),
            s.rotVel(),
            battery > 0 ? battery : Double.NaN,
            robot.areMotorsEnabled(),
            stalled,
            mode(),
            score));
  }

  private String mode() {
    if (driver != null && driver.isDriving()) {
      return "teleop";
    }
    if (path == null) {
      return "ready";
    }
    return switch (path.getState()) {
      case NOT_INITIALIZED -> "ready";
      case PLANNING_PATH -> "planning a path";
      case MOVING_TO_GOAL -> "going to the goal";
      case REACHED_GOAL -> "goal reached";
      case FAILED_PLAN -> "no path to the goal";
      case FAILED_MOVE -> "could not reach the goal";
      case ABORTED_PATHPLAN -> "stopped";
      case GOAL_OUT_OF_BOUNDS -> "goal outside the map";
      case GOAL_IN_OBSTACLE -> "goal in an obstacle";
    };
  }

  static Points particles(List<ArPose> samples) {
    int n = samples.size();
    int step = Math.max(1, (n + MAX_PARTICLES - 1) / MAX_PARTICLES);
    Points.Builder b = Points.builder(n / step + 1);
    for (int i = 0; i < n; i += step) {
      ArPose p = samples.get(i);
      b.add(p.x(), p.y());
    }
    return b.build();
  }

  private static Points outline(ArRobotParams p, ArPose at) {
    double front = p.getRobotLengthFront() > 0 ? p.getRobotLengthFront() : p.getRobotLength() / 2;
    double rear = p.getRobotLengthRear() > 0 ? p.getRobotLengthRear() : p.getRobotLength() / 2;
    double half = p.getRobotWidth() / 2;
    ArTransform t = ArTransform.ofPose(at);
    double[][] corners = {{front, -half}, {front, half}, {-rear, half}, {-rear, -half}};
    Points.Builder b = Points.builder(4);
    for (double[] c : corners) {
      b.add(t.transformX(c[0], c[1]), t.transformY(c[0], c[1]));
    }
    return b.build();
  }

  private static Points sonarOrigins(RobotStatus s) {
    Points.Builder b = Points.builder(s.sonars().size());
    for (ArSensorReading r : s.sonars()) {
      if (r.range() > 0) {
        ArTransform t = ArTransform.ofPose(r.poseTaken());
        b.add(t.transformX(r.sensorX(), r.sensorY()), t.transformY(r.sensorX(), r.sensorY()));
      }
    }
    return b.build();
  }

  private static Points sonarEchoes(RobotStatus s) {
    Points.Builder b = Points.builder(s.sonars().size());
    for (ArSensorReading r : s.sonars()) {
      if (r.range() > 0) {
        b.add(r.x(), r.y());
      }
    }
    return b.build();
  }
}
