package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import org.jaria.web.json.Json;

/**
 * The JSON schemas of the messages the web view publishes: Foxglove's well-known types (which
 * Foxglove and Lichtblick draw in their 3D panel by the schema name) and two of JAria's own (the
 * robot's status and the clock, shown in a raw-message or plot panel). Each schema lists the fields
 * this server fills; they are written here from the types' field lists, in JSON Schema's {@code
 * jsonschema} encoding.
 */
public final class Schemas {

  private Schemas() {}

  /** A schema fragment. */
  private interface S extends Json.Body {}

  private static final S NUMBER = type("number");
  private static final S INTEGER = type("integer");
  private static final S STRING = type("string");
  private static final S BOOLEAN = type("boolean");
  private static final S TIME = object("time", field("sec", INTEGER), field("nsec", INTEGER));
  private static final S VECTOR3 =
      object("foxglove.Vector3", field("x", NUMBER), field("y", NUMBER), field("z", NUMBER));
  private static final S QUATERNION =
      object(
          "foxglove.Quaternion",
          field("x", NUMBER),
          field("y", NUMBER),
          field("z", NUMBER),
          field("w", NUMBER));
  private static final S POSE =
      object("foxglove.Pose", field("position", VECTOR3), field("orientation", QUATERNION));
  private static final S COLOR =
      object(
          "foxglove.Color",
          field("r", NUMBER),
          field("g", NUMBER),
          field("b", NUMBER),
          field("a", NUMBER));
  private static final S PACKED_FIELD =
      object(
          "foxglove.PackedElementField",
          field("name", STRING),
          field("offset", INTEGER),
          field("type", INTEGER));
  private static final S BYTES =
      g -> {
        g.writeStartObject();
        g.writeStringField("type", "string");
        g.writeStringField("contentEncoding", "base64");
        g.writeEndObject();
      };
  private static final S LINE =
      object(
          "foxglove.LinePrimitive",
          field("type", INTEGER),
          field("pose", POSE),
          field("thickness", NUMBER),
          field("scale_invariant", BOOLEAN),
          field("points", array(VECTOR3)),
          field("color", COLOR),
          field("colors", array(COLOR)),
          field("indices", array(INTEGER)));
  private static final S ARROW =
      object(
          "foxglove.ArrowPrimitive",
          field("pose", POSE),
          field("shaft_length", NUMBER),
          field("shaft_diameter", NUMBER),
          field("head_length", NUMBER),
          field("head_diameter", NUMBER),
          field("color", COLOR));
  private static final S TEXT =
      object(
          "foxglove.TextPrimitive",
          field("pose", POSE),
          field("billboard", BOOLEAN),
          field("font_size", NUMBER),
          field("scale_invariant", BOOLEAN),
          field("color", COLOR),
          field("text", STRING));
  private static final S ENTITY =
      object(
          "foxglove.SceneEntity",
          field("timestamp", TIME),
          field("frame_id", STRING),
          field("id", STRING),
          field("lifetime", object("duration", field("sec", INTEGER), field("nsec", INTEGER))),
          field("frame_locked", BOOLEAN),
          field("metadata", array(object("foxglove.KeyValuePair", field("key", STRING)))),
          field("arrows", array(ARROW)),
          field("cubes", array(object("foxglove.CubePrimitive", field("pose", POSE)))),
          field("spheres", array(object("foxglove.SpherePrimitive", field("pose", POSE)))),
          field("cylinders", array(object("foxglove.CylinderPrimitive", field("pose", POSE)))),
          field("lines", array(LINE)),
          field("triangles", array(object("foxglove.TriangleListPrimitive", field("pose", POSE)))),
          field("texts", array(TEXT)),
          field("models", array(object("foxglove.ModelPrimitive", field("pose", POSE)))));

  /** {@code foxglove.PoseInFrame}: a pose with its time and frame. */
  public static final String POSE_IN_FRAME =
      schema(
          "foxglove.PoseInFrame",
          field("timestamp", TIME),
          field("frame_id", STRING),
          field("pose", POSE));

  /** {@code foxglove.PosesInFrame}: a list of poses (a planned path). */
  public static final String POSES_IN_FRAME =
      schema(
          "foxglove.PosesInFrame",
          field("timestamp", TIME),
          field("frame_id", STRING),
          field("poses", array(POSE)));

  /** {@code foxglove.FrameTransform}: where a child frame is in its parent. */
  public static final String FRAME_TRANSFORM =
      schema(
          "foxglove.FrameTransform",
          field("timestamp", TIME),
          field("parent_frame_id", STRING),
          field("child_frame_id", STRING),
          field("translation", VECTOR3),
          field("rotation", QUATERNION));

  /** {@code foxglove.LaserScan}: one planar scan. */
  public static final String LASER_SCAN =
      schema(
          "foxglove.LaserScan",
          field("timestamp", TIME),
          field("frame_id", STRING),
          field("pose", POSE),
          field("start_angle", NUMBER),
          field("end_angle", NUMBER),
          field("ranges", array(NUMBER)),
          field("intensities", array(NUMBER)));

  /** {@code foxglove.PointCloud}: packed points (sonar echoes, particles). */
  public static final String POINT_CLOUD =
      schema(
          "foxglove.PointCloud",
          field("timestamp", TIME),
          field("frame_id", STRING),
          field("pose", POSE),
          field("point_stride", INTEGER),
          field("fields", array(PACKED_FIELD)),
          field("data", BYTES));

  /** {@code foxglove.SceneUpdate}: entities of lines, arrows and texts (the map, the robots). */
  public static final String SCENE_UPDATE =
      schema(
          "foxglove.SceneUpdate",
          field(
              "deletions",
              array(
                  object(
                      "foxglove.SceneEntityDeletion",
                      field("timestamp", TIME),
                      field("type", INTEGER),
                      field("id", STRING)))),
          field("entities", array(ENTITY)));

  /** {@code jaria.RobotStatus}: speeds, battery, motors, mode and localization score. */
  public static final String ROBOT_STATUS =
      schema(
          "jaria.RobotStatus",
          field("timestamp", TIME),
          field("robot", STRING),
          field("model", STRING),
          field("vel", NUMBER),
          field("rot_vel", NUMBER),
          field("battery_volts", NUMBER),
          field("motors_enabled", BOOLEAN),
          field("stalled", BOOLEAN),
          field("mode", STRING),
          field("localization_score", NUMBER),
          field("x", NUMBER),
          field("y", NUMBER),
          field("th", NUMBER),
          field(
              "goal",
              object("jaria.Goal", field("x", NUMBER), field("y", NUMBER), field("th", NUMBER))));

  /** {@code jaria.Clock}: simulated time, speed-up and whether the simulation is paused. */
  public static final String CLOCK =
      schema(
          "jaria.Clock",
          field("timestamp", TIME),
          field("seconds", NUMBER),
          field("speedup", NUMBER),
          field("paused", BOOLEAN),
          field("simulated", BOOLEAN));

  private record Field(String name, S schema) {}

  private static Field field(String name, S schema) {
    return new Field(name, schema);
  }

  private static S type(String t) {
    return g -> {
      g.writeStartObject();
      g.writeStringField("type", t);
      g.writeEndObject();
    };
  }

  private static S array(S items) {
    return g -> {
      g.writeStartObject();
      g.writeStringField("type", "array");
      g.writeFieldName("items");
      items.write(g);
      g.writeEndObject();
    };
  }

  private static S object(String title, Field... fields) {
    return g -> writeObject(g, title, fields);
  }

  private static void writeObject(JsonGenerator g, String title, Field... fields)
      throws IOException {
    g.writeStartObject();
    g.writeStringField("title", title);
    g.writeStringField("type", "object");
    g.writeObjectFieldStart("properties");
    for (Field f : fields) {
      g.writeFieldName(f.name());
      f.schema().write(g);
    }
    g.writeEndObject();
    g.writeEndObject();
  }

  private static String schema(String title, Field... fields) {
    return Json.string(g -> writeObject(g, title, fields));
  }
}
