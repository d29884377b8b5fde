package org.jaria.web.foxglove;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.web.json.Json;
import org.jaria.web.model.ClockFrame;
import org.jaria.web.model.LaserFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.WorldFrame;

/**
 * Turns frames into Foxglove messages (JSON encoding, Foxglove's schemas): one list of messages per
 * frame, encoded once whatever the number of viewers. A plain function of its input.
 */
public final class FrameEncoder {

  /** Foxglove's FLOAT32 in a packed field. */
  private static final int FLOAT32 = 7;

  private FrameEncoder() {}

  /**
   * The messages of one frame: {@code /clock}, {@code /robots}, one {@code /tf} per robot, and each
   * robot's topics that its frame has data for (the believed pose, particles and path only where
   * something localizes it; the laser only if it has one).
   */
  public static List<Message> encode(WorldFrame f) {
    long t = f.clock().timeNanos();
    List<Message> out = new ArrayList<>(4 + 8 * f.robots().size());
    out.add(msg(TopicKind.CLOCK, null, t, Json.bytes(g -> clock(g, f.clock()))));
    out.add(msg(TopicKind.ROBOTS, null, t, Json.bytes(g -> RobotScene.write(g, t, f.robots()))));
    for (RobotFrame r : f.robots()) {
      ArPose shown = r.shownPose();
      if (shown != null) {
        out.add(msg(TopicKind.TF, r.name(), t, Json.bytes(g -> transform(g, t, r.name(), shown))));
      }
      if (r.truePose() != null) {
        out.add(msg(TopicKind.TRUE_POSE, r.name(), t, poseInFrame(t, r.truePose())));
      }
      if (r.believedPose() != null) {
        out.add(msg(TopicKind.POSE, r.name(), t, poseInFrame(t, r.believedPose())));
        out.add(msg(TopicKind.PARTICLES, r.name(), t, pointCloud(t, r.particles())));
        out.add(msg(TopicKind.PATH, r.name(), t, Json.bytes(g -> path(g, t, r.path()))));
      }
      out.add(msg(TopicKind.SONAR, r.name(), t, pointCloud(t, r.sonarEchoes())));
      if (r.laser() != null) {
        out.add(msg(TopicKind.LASER, r.name(), t, Json.bytes(g -> laser(g, t, r.laser()))));
      }
      out.add(msg(TopicKind.STATUS, r.name(), t, Json.bytes(g -> status(g, t, r))));
    }
    return out;
  }

  /** The {@code /map} message of {@code map}. */
  public static Message encodeMap(MapLayer map, long timeNanos) {
    return msg(TopicKind.MAP, null, timeNanos, Json.bytes(g -> MapScene.write(g, timeNanos, map)));
  }

  private static Message msg(TopicKind k, String robot, long t, byte[] payload) {
    return new Message(k.topic(robot), k, t, payload);
  }

  static byte[] poseInFrame(long t, ArPose p) {
    return Json.bytes(
        g -> {
          g.writeStartObject();
          Encoding.time(g, "timestamp", t);
          g.writeStringField("frame_id", Encoding.MAP_FRAME);
          Encoding.pose(g, "pose", p);
          g.writeEndObject();
        });
  }

  /** Points as a cloud of float32 x, y in metres, little-endian, base64 as JSON wants bytes. */
  static byte[] pointCloud(long t, Points pts) {
    ByteBuffer data = ByteBuffer.allocate(8 * pts.size()).order(ByteOrder.LITTLE_ENDIAN);
    for (int i = 0; i < pts.size(); i++) {
      data.putFloat(pts.x(i) / 1000f).putFloat(pts.y(i) / 1000f);
    }
    return Json.bytes(
        g -> {
          g.writeStartObject();
          Encoding.time(g, "timestamp", t);
          g.writeStringField("frame_id", Encoding.MAP_FRAME);
          Encoding.pose(g, "pose", ArPose.ORIGIN);
          g.writeNumberField("point_stride", 8);
          g.writeArrayFieldStart("fields");
          packedField(g, "x", 0);
          packedField(g, "y", 4);
          g.writeEndArray();
          g.writeFieldName("data");
          g.writeBinary(data.array());
          g.writeEndObject();
        });
  }

  private static void packedField(JsonGenerator g, String name, int offset) throws IOException {
    g.writeStartObject();
    g.writeStringField("name", name);
    g.writeNumberField("offset", offset);
    g.writeNumberField("type", FLOAT32);
    g.writeEndObject();
  }

  private static void transform(JsonGenerator g, long t, String robot, ArPose p)
      throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", t);
    g.writeStringField("parent_frame_id", Encoding.MAP_FRAME);
    g.writeStringField("child_frame_id", TopicKind.safeName(robot) + "/base_link");
    Encoding.vector(g, "translation", p.x(), p.y());
    Encoding.quaternion(g, "rotation", p.th());
    g.writeEndObject();
  }

  private static void path(JsonGenerator g, long t, Points path) throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", t);
    g.writeStringField("frame_id", Encoding.MAP_FRAME);
    g.writeArrayFieldStart("poses");
    for (int i = 0; i < path.size(); i++) {
      // Each pose faces the next point, so Foxglove's arrows show the way along the path.
      int j = Math.min(i + 1, path.size() - 1);
      int k = j == i ? Math.max(i - 1, 0) : i;
      double th =
          Math.toDegrees(
              Math.atan2(
                  path.y(j) - path.y(k),
                  path.x(j) - path.x(k) == 0 ? 1e-9 : path.x(j) - path.x(k)));
      g.writeStartObject();
      Encoding.vector(g, "position", path.x(i), path.y(i));
      Encoding.quaternion(g, "orientation", th);
      g.writeEndObject();
    }
    g.writeEndArray();
    g.writeEndObject();
  }

  private static void laser(JsonGenerator g, long t, LaserFrame l) throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", t);
    g.writeStringField("frame_id", Encoding.MAP_FRAME);
    Encoding.pose(g, "pose", l.origin());
    double start = Math.toRadians(l.startDeg());
    g.writeNumberField("start_angle", Encoding.round(start));
    g.writeNumberField(
        "end_angle",
        Encoding.round(start + Math.toRadians(l.incrementDeg()) * Math.max(l.size() - 1, 0)));
    g.writeArrayFieldStart("ranges");
    for (int k = 0; k < l.size(); k++) {
      g.writeNumber(Encoding.metres(Math.max(l.range(k), 0)));
    }
    g.writeEndArray();
    g.writeArrayFieldStart("intensities");
    g.writeEndArray();
    g.writeEndObject();
  }

  private static void status(JsonGenerator g, long t, RobotFrame r) throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", t);
    g.writeStringField("robot", r.name());
    g.writeStringField("model", r.model());
    g.writeNumberField("vel", Encoding.round(r.status().vel()));
    g.writeNumberField("rot_vel", Encoding.round(r.status().rotVel()));
    numberOrNull(g, "battery_volts", r.status().batteryVolts());
    g.writeBooleanField("motors_enabled", r.status().motorsEnabled());
    g.writeBooleanField("stalled", r.status().stalled());
    g.writeStringField("mode", r.status().mode());
    numberOrNull(g, "localization_score", r.status().localizationScore());
    ArPose p = r.believedPose() != null ? r.believedPose() : r.truePose();
    if (p != null) {
      g.writeNumberField("x", Encoding.round(p.x()));
      g.writeNumberField("y", Encoding.round(p.y()));
      g.writeNumberField("th", Encoding.round(p.th()));
    }
    if (r.goal() != null) {
      g.writeObjectFieldStart("goal");
      g.writeNumberField("x", Encoding.round(r.goal().x()));
      g.writeNumberField("y", Encoding.round(r.goal().y()));
      g.writeNumberField("th", Encoding.round(r.goal().th()));
      g.writeEndObject();
    }
    g.writeEndObject();
  }

  private static void clock(JsonGenerator g, ClockFrame c) throws IOException {
    g.writeStartObject();
    Encoding.time(g, "timestamp", c.timeNanos());
    g.writeNumberField("seconds", c.timeNanos() / 1e9);
    numberOrNull(g, "speedup", c.speedup());
    g.writeBooleanField("paused", c.paused());
    g.writeBooleanField("simulated", c.simulated());
    g.writeEndObject();
  }

  /** JSON has no NaN: an unknown number is null. */
  private static void numberOrNull(JsonGenerator g, String field, double v) throws IOException {
    if (Double.isFinite(v)) {
      g.writeNumberField(field, Encoding.round(v));
    } else {
      g.writeNullField(field);
    }
  }
}
