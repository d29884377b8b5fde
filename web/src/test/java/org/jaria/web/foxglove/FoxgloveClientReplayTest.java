package org.jaria.web.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.core.JsonFactory;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.jaria.web.control.ControlCommand;
import org.jaria.web.json.JsonValues;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Replays an exchange recorded by hand between Foxglove's own client library ({@code
 * @foxglove/ws-protocol} 0.8.0 on Node, the library Foxglove and Lichtblick connect with) and
 * {@code ./jaria web --allow-control}: every frame each way, and what the library made of the
 * server's frames. The server's frames must mean to this project's reading what they meant to the
 * library, and the library's own frames (subscribe, advertise, a Twist on {@code /cmd_vel}) must
 * be understood by the server's side of the protocol.
 */
class FoxgloveClientReplayTest {

  private static List<Map<?, ?>> frames;
  private static List<Map<?, ?>> parsed;

  @BeforeAll
  static void load() throws Exception {
    try (InputStream in =
        FoxgloveClientReplayTest.class.getResourceAsStream("ws-protocol-exchange.json")) {
      String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
      Map<?, ?> all = (Map<?, ?>) JsonValues.read(text, new JsonFactory(), Integer.MAX_VALUE);
      frames = cast(all.get("frames"));
      parsed = cast(all.get("parsed"));
    }
  }

  @SuppressWarnings("unchecked")
  private static List<Map<?, ?>> cast(Object o) {
    return (List<Map<?, ?>>) o;
  }

  private static List<Map<?, ?>> events(String kind) {
    return parsed.stream().filter(e -> e.get("event").equals(kind)).toList();
  }

  private static Map<?, ?> json(String text) throws Exception {
    return (Map<?, ?>) JsonValues.read(text, new JsonFactory(), Integer.MAX_VALUE);
  }

  /** The channels the server advertised, as the server's frames say them. */
  private static List<Map<?, ?>> advertisedChannels() throws Exception {
    List<Map<?, ?>> out = new ArrayList<>();
    for (Map<?, ?> f : frames) {
      if (f.get("dir").equals("server") && f.get("text") instanceof String t) {
        Map<?, ?> m = json(t);
        if (m.get("op").equals("advertise")) {
          out.addAll(cast(m.get("channels")));
        }
      }
    }
    return out;
  }

  @Test
  void theLibraryReadTheServerInfoAndEveryChannelAsTheServerMeantThem() throws Exception {
    Map<?, ?> info = json((String) frames.get(0).get("text"));
    assertEquals("serverInfo", info.get("op"));
    Map<?, ?> event = events("serverInfo").get(0);
    assertEquals(info.get("name"), event.get("name"));
    assertEquals(info.get("capabilities"), event.get("capabilities"));
    List<Map<?, ?>> channels = advertisedChannels();
    List<Map<?, ?>> seen = events("advertise");
    assertEquals(channels.size(), seen.size());
    assertTrue(channels.size() >= 10, "map, poses and laser at least: " + channels.size());
    for (int i = 0; i < channels.size(); i++) {
      Map<?, ?> c = channels.get(i);
      Map<?, ?> e = seen.get(i);
      assertEquals(((Number) c.get("id")).longValue(), ((Number) e.get("id")).longValue());
      for (String k : List.of("topic", "schemaName", "encoding", "schemaEncoding")) {
        assertEquals(c.get(k), e.get(k), k);
      }
    }
    List<String> topics = channels.stream().map(c -> String.valueOf(c.get("topic"))).toList();
    for (String t :
        List.of("/map", "/p3dx-sh_1/true_pose", "/p3dx-sh_1/laser", "/p3dx-sh_1/pose")) {
      assertTrue(topics.contains(t), t + " in " + topics);
    }
  }

  @Test
  void everyMessageFrameMeantToTheLibraryWhatItMeansHere() throws Exception {
    Map<Long, String> topicOfSubscription = new HashMap<>();
    Map<Long, String> topicOfChannel = new HashMap<>();
    for (Map<?, ?> c : advertisedChannels()) {
      topicOfChannel.put(((Number) c.get("id")).longValue(), (String) c.get("topic"));
    }
    List<ByteBuffer> data = new ArrayList<>();
    for (Map<?, ?> f : frames) {
      if (f.get("dir").equals("client") && f.get("text") instanceof String t) {
        ClientRequest r = ClientMessages.parse(t);
        if (r instanceof ClientRequest.Subscribe s) {
          for (ClientRequest.Subscription sub : s.subscriptions()) {
            topicOfSubscription.put(sub.id(), topicOfChannel.get(sub.channelId()));
          }
        }
      } else if (f.get("dir").equals("server") && f.get("binary") instanceof String b) {
        data.add(ByteBuffer.wrap(Base64.getDecoder().decode(b)).order(ByteOrder.LITTLE_ENDIAN));
      }
    }
    List<Map<?, ?>> messages = events("message");
    assertEquals(data.size(), messages.size());
    assertTrue(messages.size() >= 20, "enough messages replayed: " + messages.size());
    for (int i = 0; i < data.size(); i++) {
      ByteBuffer d = data.get(i);
      Map<?, ?> e = messages.get(i);
      assertEquals(ServerMessages.MESSAGE_DATA, d.get(0));
      long sub = d.getInt(1) & 0xFFFFFFFFL;
      assertEquals(((Number) e.get("subscriptionId")).longValue(), sub);
      assertEquals(Long.parseLong((String) e.get("timestamp")), d.getLong(5));
      assertEquals(((Number) e.get("length")).intValue(), d.limit() - 13);
      assertEquals(e.get("topic"), topicOfSubscription.get(sub));
      byte[] body = new byte[d.limit() - 13];
      d.get(13, body);
      String payload = new String(body, StandardCharsets.UTF_8);
      assertInstanceOf(Map.class, json(payload), "every payload is a JSON object");
    }
  }

  @Test
  void theServerUnderstandsEverythingTheLibrarySent() throws Exception {
    List<Channel> channels = new ArrayList<>();
    for (Map<?, ?> c : advertisedChannels()) {
      channels.add(
          new Channel(((Number) c.get("id")).intValue(), (String) c.get("topic"), TopicKind.CLOCK));
    }
    ClientSession session = new ClientSession(true);
    int subscribes = 0;
    ControlCommand drive = null;
    for (Map<?, ?> f : frames) {
      if (!f.get("dir").equals("client")) {
        continue;
      }
      ClientRequest r =
          f.get("text") instanceof String t
              ? ClientMessages.parse(t)
              : ClientMessages.parse(
                  ByteBuffer.wrap(Base64.getDecoder().decode((String) f.get("binary"))));
      ClientSession.Outcome o = session.handle(r, channels);
      assertNull(o.problem(), r + " -> " + o.replies());
      subscribes += r instanceof ClientRequest.Subscribe ? 1 : 0;
      if (o.published() != null) {
        assertEquals(ControlCommand.DRIVE_TOPIC, o.published().topic());
        drive = ControlCommand.parse(o.published().topic(), o.published().payload());
      }
    }
    assertEquals(channels.size(), subscribes, "one subscribe per channel, as the library does");
    assertEquals(new ControlCommand.Drive(200, Math.toDegrees(0.1)), drive);
  }
}
