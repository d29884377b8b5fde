package org.jaria.web.foxglove;

/**
 * What the web view publishes, one kind per topic: four topics for the whole world and seven for
 * each robot ({@code /NAME/...}). Each has a schema; Foxglove's 3D panel draws the {@code
 * foxglove.*} ones.
 */
public enum TopicKind {
  /** The map's walls, points, goals and forbidden areas (sent on subscribing and on a change). */
  MAP("/map", "foxglove.SceneUpdate", Schemas.SCENE_UPDATE, false),
  /** Every robot's outline and heading. */
  ROBOTS("/robots", "foxglove.SceneUpdate", Schemas.SCENE_UPDATE, false),
  /** Where each robot's frame ({@code NAME/base_link}) is in the map frame. */
  TF("/tf", "foxglove.FrameTransform", Schemas.FRAME_TRANSFORM, false),
  /** Simulated time, speed-up, paused. */
  CLOCK("/clock", "jaria.Clock", Schemas.CLOCK, false),
  /** Where the simulator has the robot. */
  TRUE_POSE("true_pose", "foxglove.PoseInFrame", Schemas.POSE_IN_FRAME, true),
  /** Where the robot believes it is. */
  POSE("pose", "foxglove.PoseInFrame", Schemas.POSE_IN_FRAME, true),
  /** The localization's particles. */
  PARTICLES("particles", "foxglove.PointCloud", Schemas.POINT_CLOUD, true),
  /** Where the sonar got echoes. */
  SONAR("sonar", "foxglove.PointCloud", Schemas.POINT_CLOUD, true),
  /** The laser's scan. */
  LASER("laser", "foxglove.LaserScan", Schemas.LASER_SCAN, true),
  /** The planned path. */
  PATH("path", "foxglove.PosesInFrame", Schemas.POSES_IN_FRAME, true),
  /** Speeds, battery, mode. */
  STATUS("status", "jaria.RobotStatus", Schemas.ROBOT_STATUS, true);

  private final String name;
  private final String schemaName;
  private final String schema;
  private final boolean perRobot;

  TopicKind(String name, String schemaName, String schema, boolean perRobot) {
    this.name = name;
    this.schemaName = schemaName;
    this.schema = schema;
    this.perRobot = perRobot;
  }

  /** The topic's name ({@code /map}), or its last part for a robot's topic ({@code laser}). */
  public String topicName() {
    return name;
  }

  /** The schema's name ({@code foxglove.LaserScan}). */
  public String schemaName() {
    return schemaName;
  }

  /** The JSON schema. */
  public String schema() {
    return schema;
  }

  /** Whether each robot has a topic of this kind. */
  public boolean perRobot() {
    return perRobot;
  }

  /** The topic of this kind for {@code robot} (ignored for a world topic). */
  public String topic(String robot) {
    return perRobot ? "/" + safeName(robot) + "/" + name : name;
  }

  /**
   * A robot name as a topic part: letters, digits, {@code _} and {@code -} kept, anything else
   * {@code _} (a topic name has no spaces or slashes of its own).
   */
  public static String safeName(String robot) {
    StringBuilder sb = new StringBuilder(robot.length());
    for (int i = 0; i < robot.length(); i++) {
      char c = robot.charAt(i);
      boolean ok =
          (c >= 'a' && c <= 'z')
              || (c >= 'A' && c <= 'Z')
              || (c >= '0' && c <= '9')
              || c == '_'
              || c == '-';
      sb.append(ok ? c : '_');
    }
    return sb.length() == 0 ? "_" : sb.toString();
  }
}
