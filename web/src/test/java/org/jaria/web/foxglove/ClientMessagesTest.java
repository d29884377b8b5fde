package org.jaria.web.foxglove;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** What clients send is read, and everything else is refused with a reason, never thrown. */
class ClientMessagesTest {

  @Test
  void readsTheOperationsItSupports() {
    assertEquals(
        new ClientRequest.Subscribe(
            List.of(new ClientRequest.Subscription(0, 1), new ClientRequest.Subscription(7, 2))),
        ClientMessages.parse(
            "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":0,\"channelId\":1},"
                + "{\"id\":7,\"channelId\":2}]}"));
    assertEquals(
        new ClientRequest.Unsubscribe(List.of(3L, 4L)),
        ClientMessages.parse("{\"op\":\"unsubscribe\",\"subscriptionIds\":[3,4]}"));
    assertEquals(
        new ClientRequest.Advertise(
            List.of(new ClientRequest.ClientChannel(1, "/cmd_vel", "json", "geometry_msgs/Twist"))),
        ClientMessages.parse(
            "{\"op\":\"advertise\",\"channels\":[{\"id\":1,\"topic\":\"/cmd_vel\","
                + "\"encoding\":\"json\",\"schemaName\":\"geometry_msgs/Twist\"}]}"));
    assertEquals(
        new ClientRequest.Unadvertise(List.of(1L)),
        ClientMessages.parse("{\"op\":\"unadvertise\",\"channelIds\":[1]}"));
    assertEquals(
        new ClientRequest.Unknown("getParameters"),
        ClientMessages.parse("{\"op\":\"getParameters\",\"parameterNames\":[]}"));
  }

  @ParameterizedTest
  @ValueSource(
      strings = {
        "",
        "not json",
        "[1,2]",
        "{\"op\":5}",
        "{\"subscriptions\":[]}",
        "{\"op\":\"subscribe\"",
        "{\"op\":\"subscribe\",\"subscriptions\":{}}",
        "{\"op\":\"subscribe\",\"subscriptions\":[5]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":-1,\"channelId\":1}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1.5,\"channelId\":1}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":4294967296,\"channelId\":1}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1}]}",
        "{\"op\":\"unsubscribe\",\"subscriptionIds\":[\"a\"]}",
        "{\"op\":\"advertise\",\"channels\":[{\"id\":1}]}",
        "{\"op\":\"subscribe\"} trailing",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":99999999999999999999999999999999999999999999,\"channelId\":1}]}"
      })
  void malformedTextIsMalformed(String text) {
    assertInstanceOf(ClientRequest.Malformed.class, ClientMessages.parse(text), text);
  }

  @Test
  void deepNestingLongListsAndHugeStringsAreRefused() {
    String deep = "[".repeat(5000) + "]".repeat(5000);
    assertInstanceOf(ClientRequest.Malformed.class, ClientMessages.parse(deep));
    StringBuilder ids = new StringBuilder();
    for (int i = 0; i < ClientMessages.MAX_ENTRIES + 1; i++) {
      ids.append(i == 0 ? "" : ",").append(i);
    }
    ClientRequest r =
        ClientMessages.parse("{\"op\":\"unsubscribe\",\"subscriptionIds\":[" + ids + "]}");
    assertInstanceOf(ClientRequest.Malformed.class, r);
    assertTrue(((ClientRequest.Malformed) r).reason().contains("at most"), r.toString());
    String huge = "{\"op\":\"" + "x".repeat(100_000) + "\"}";
    assertInstanceOf(ClientRequest.Malformed.class, ClientMessages.parse(huge));
    StringBuilder many = new StringBuilder("{\"op\":\"x\",\"a\":[");
    for (int i = 0; i < 10_000; i++) {
      many.append(i == 0 ? "" : ",").append("0");
    }
    assertInstanceOf(ClientRequest.Malformed.class, ClientMessages.parse(many + "]}"));
  }

  @Test
  void binaryMessagesArePublishesOnAClientChannel() {
    byte[] payload = "{\"a\":1}".getBytes(StandardCharsets.UTF_8);
    ByteBuffer b = ByteBuffer.allocate(5 + payload.length).order(ByteOrder.LITTLE_ENDIAN);
    b.put((byte) 1).putInt(0xFFFFFFFE).put(payload).flip();
    ClientRequest r = ClientMessages.parse(b);
    ClientRequest.Publish p = assertInstanceOf(ClientRequest.Publish.class, r);
    assertEquals(0xFFFFFFFEL, p.channelId());
    assertArrayEquals(payload, p.payload());
    assertEquals(5 + payload.length, b.remaining(), "the caller's buffer is left as it was");
  }

  @Test
  void shortOrUnknownBinaryMessagesAreRefused() {
    assertInstanceOf(
        ClientRequest.Malformed.class, ClientMessages.parse(ByteBuffer.wrap(new byte[] {1, 0, 0})));
    assertInstanceOf(ClientRequest.Malformed.class, ClientMessages.parse(ByteBuffer.allocate(0)));
    assertEquals(
        new ClientRequest.Unknown("binary opcode 2"),
        ClientMessages.parse(ByteBuffer.wrap(new byte[] {2, 0, 0, 0, 0, 9})));
  }
}
