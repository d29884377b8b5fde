package org.jaria.web.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import org.jaria.geom.ArPose;
import org.jaria.web.json.JsonValues;
import org.jaria.web.model.ClockFrame;
import org.jaria.web.model.LaserFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.RobotStatus;
import org.jaria.web.model.WorldFrame;
import org.junit.jupiter.api.Test;

/** Frames become Foxglove messages in Foxglove's units, with the fields its schemas name. */
class FrameEncoderTest {

  static final RobotFrame ROBOT =
      new RobotFrame(
          "bot 1",
          "p3dx-sh",
          new ArPose(1500, -2000, 90),
          new ArPose(1510, -1990, 88),
          Points.of(200, -100, 200, 100, -200, 100, -200, -100),
          Points.of(1500, -2000),
          Points.of(1500, -1000),
          new LaserFrame(new ArPose(1600, -2000, 90), -90, 1, new int[] {1000, 2000, 0}),
          Points.of(1000, 2000, -500, 250),
          Points.of(1510, -1990, 3000, -1990),
          new ArPose(3000, -1990, 0),
          new RobotStatus(250, -10, 12.5, true, false, "going to the goal", 0.75));

  static final WorldFrame FRAME =
      new WorldFrame(new ClockFrame(2_500_000_000L, 2, false, true), List.of(ROBOT));

  static Map<?, ?> json(Message m) throws Exception {
    return (Map<?, ?>) JsonValues.read(m.json());
  }

  static Message topic(List<Message> ms, String topic) {
    return ms.stream().filter(m -> m.topic().equals(topic)).findFirst().orElseThrow();
  }

  static double num(Object o) {
    return ((Number) o).doubleValue();
  }

  @Test
  void everyTopicOfTheFrameIsThereWithItsSchema() {
    List<Message> ms = FrameEncoder.encode(FRAME);
    assertEquals(
        List.of(
            "/clock",
            "/robots",
            "/tf",
            "/bot_1/true_pose",
            "/bot_1/pose",
            "/bot_1/particles",
            "/bot_1/path",
            "/bot_1/sonar",
            "/bot_1/laser",
            "/bot_1/status"),
        ms.stream().map(Message::topic).toList());
    for (Message m : ms) {
      assertEquals(2_500_000_000L, m.timeNanos());
    }
    assertEquals("foxglove.LaserScan", topic(ms, "/bot_1/laser").kind().schemaName());
  }

  @Test
  void posesAreInMetresWithAQuaternionAboutZ() throws Exception {
    Map<?, ?> m = json(topic(FrameEncoder.encode(FRAME), "/bot_1/true_pose"));
    assertEquals("map", m.get("frame_id"));
    Map<?, ?> t = (Map<?, ?>) m.get("timestamp");
    assertEquals(2L, t.get("sec"));
    assertEquals(500_000_000L, t.get("nsec"));
    Map<?, ?> pose = (Map<?, ?>) m.get("pose");
    Map<?, ?> pos = (Map<?, ?>) pose.get("position");
    assertEquals(1.5, num(pos.get("x")));
    assertEquals(-2.0, num(pos.get("y")));
    Map<?, ?> q = (Map<?, ?>) pose.get("orientation");
    assertEquals(Math.sqrt(0.5), num(q.get("z")), 1e-6);
    assertEquals(Math.sqrt(0.5), num(q.get("w")), 1e-6);
    assertEquals(90, Encoding.headingDeg(num(q.get("z")), num(q.get("w"))), 1e-4);
  }

  @Test
  void pointCloudsCarryFloat32MetresInBase64() throws Exception {
    Map<?, ?> m = json(topic(FrameEncoder.encode(FRAME), "/bot_1/particles"));
    assertEquals(8L, m.get("point_stride"));
    List<?> fields = (List<?>) m.get("fields");
    assertEquals("x", ((Map<?, ?>) fields.get(0)).get("name"));
    assertEquals(7L, ((Map<?, ?>) fields.get(1)).get("type"));
    ByteBuffer b =
        ByteBuffer.wrap(Base64.getDecoder().decode((String) m.get("data")))
            .order(ByteOrder.LITTLE_ENDIAN);
    assertEquals(16, b.remaining());
    assertEquals(1.0f, b.getFloat());
    assertEquals(2.0f, b.getFloat());
    assertEquals(-0.5f, b.getFloat());
    assertEquals(0.25f, b.getFloat());
  }

  @Test
  void theLaserScanSpansItsBeamsAndMissingReturnsAreZero() throws Exception {
    Map<?, ?> m = json(topic(FrameEncoder.encode(FRAME), "/bot_1/laser"));
    assertEquals(-Math.PI / 2, num(m.get("start_angle")), 1e-6);
    assertEquals(-Math.PI / 2 + 2 * Math.PI / 180, num(m.get("end_angle")), 1e-6);
    assertEquals(
        List.of(1.0, 2.0, 0.0),
        ((List<?>) m.get("ranges")).stream().map(FrameEncoderTest::num).toList());
    Map<?, ?> pos = (Map<?, ?>) ((Map<?, ?>) m.get("pose")).get("position");
    assertEquals(1.6, num(pos.get("x")));
  }

  @Test
  void theStatusSaysNullForWhatIsNotKnown() throws Exception {
    RobotFrame noBattery =
        ROBOT.withNavigation(
            ROBOT.believedPose(),
            Points.EMPTY,
            Points.EMPTY,
            null,
            new RobotStatus(0, 0, Double.NaN, false, true, "no client", Double.NaN));
    Message m =
        topic(
            FrameEncoder.encode(new WorldFrame(FRAME.clock(), List.of(noBattery))),
            "/bot_1/status");
    Map<?, ?> s = json(m);
    assertNull(s.get("battery_volts"));
    assertTrue(s.containsKey("battery_volts"));
    assertEquals(true, s.get("stalled"));
    Map<?, ?> full = json(topic(FrameEncoder.encode(FRAME), "/bot_1/status"));
    assertEquals(12.5, num(full.get("battery_volts")));
    assertEquals("going to the goal", full.get("mode"));
    assertEquals(3000.0, num(((Map<?, ?>) full.get("goal")).get("x")));
  }

  @Test
  void aRobotWithoutLocalizationHasNoBelievedPoseParticlesOrPath() {
    RobotFrame sim =
        new RobotFrame(
            "r",
            "p3dx-sh",
            ArPose.ORIGIN,
            null,
            Points.EMPTY,
            Points.EMPTY,
            Points.EMPTY,
            null,
            Points.EMPTY,
            Points.EMPTY,
            null,
            ROBOT.status());
    List<String> topics =
        FrameEncoder.encode(new WorldFrame(FRAME.clock(), List.of(sim))).stream()
            .map(Message::topic)
            .toList();
    assertEquals(
        List.of("/clock", "/robots", "/tf", "/r/true_pose", "/r/sonar", "/r/status"), topics);
  }

  @Test
  void theMapIsFourEntitiesOfLinesArrowsAndTexts() throws Exception {
    MapLayer map =
        new MapLayer(
            "test",
            Points.of(0, 0, 1000, 0),
            Points.of(500, 500),
            List.of(new MapLayer.Goal("Lab", "Goal", 2000, 3000, 0, false)),
            Points.EMPTY,
            List.of(Points.of(0, 0, 100, 0, 100, 100, 0, 100)),
            MapLayer.Bounds.around(Points.of(0, 0, 1000, 0)));
    Map<?, ?> m = json(FrameEncoder.encodeMap(map, 0));
    List<?> entities = (List<?>) m.get("entities");
    assertEquals(
        List.of("walls", "points", "forbidden", "goals"),
        entities.stream().map(e -> ((Map<?, ?>) e).get("id")).toList());
    Map<?, ?> walls = (Map<?, ?>) entities.get(0);
    for (String required :
        List.of(
            "arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models")) {
      assertTrue(walls.containsKey(required), required);
    }
    Map<?, ?> line = (Map<?, ?>) ((List<?>) walls.get("lines")).get(0);
    assertEquals(2L, line.get("type"));
    assertEquals(1.0, num(((Map<?, ?>) ((List<?>) line.get("points")).get(1)).get("x")));
    Map<?, ?> forbidden = (Map<?, ?>) entities.get(2);
    assertEquals(1L, ((Map<?, ?>) ((List<?>) forbidden.get("lines")).get(0)).get("type"));
    Map<?, ?> goals = (Map<?, ?>) entities.get(3);
    assertEquals("Lab", ((Map<?, ?>) ((List<?>) goals.get("texts")).get(0)).get("text"));
  }

  @Test
  void robotNamesBecomeTopicParts() {
    assertEquals("p3dx-sh_1", TopicKind.safeName("p3dx-sh_1"));
    assertEquals("a_b__c", TopicKind.safeName("a b/.c"));
    assertEquals("_", TopicKind.safeName(""));
    assertEquals("/x/laser", TopicKind.LASER.topic("x"));
    assertEquals("/map", TopicKind.MAP.topic("ignored"));
  }

  @Test
  void everySchemaIsJsonWithItsTitle() throws Exception {
    for (TopicKind k : TopicKind.values()) {
      Map<?, ?> s = (Map<?, ?>) JsonValues.read(k.schema());
      assertEquals(k.schemaName(), s.get("title"));
      assertEquals("object", s.get("type"));
    }
  }
}
