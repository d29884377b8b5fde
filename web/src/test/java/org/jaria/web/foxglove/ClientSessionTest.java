package org.jaria.web.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** One client's protocol state: decisions as values, no sockets. */
class ClientSessionTest {

  static final List<Channel> CHANNELS =
      List.of(new Channel(1, "/map", TopicKind.MAP), new Channel(2, "/clock", TopicKind.CLOCK));

  static ClientRequest.Subscribe sub(long id, long channel) {
    return new ClientRequest.Subscribe(List.of(new ClientRequest.Subscription(id, channel)));
  }

  @Test
  void subscribesToChannelsThatExist() {
    ClientSession s = new ClientSession(false);
    ClientSession.Outcome o = s.handle(sub(10, 2), CHANNELS);
    assertNull(o.problem());
    assertEquals(List.of(2L), o.subscribed());
    assertEquals(10, s.subscriptionFor(2));
    assertEquals(-1, s.subscriptionFor(1));
    ClientSession.Outcome bad = s.handle(sub(11, 99), CHANNELS);
    assertEquals(ClientSession.Problem.REFUSED, bad.problem());
    assertTrue(bad.replies().get(0).contains("no channel 99"), bad.replies().toString());
  }

  @Test
  void aSecondSubscriptionToAChannelReplacesTheFirst() {
    ClientSession s = new ClientSession(false);
    s.handle(sub(1, 2), CHANNELS);
    s.handle(sub(5, 2), CHANNELS);
    assertEquals(5, s.subscriptionFor(2));
    assertEquals(1, s.subscriptionCount());
    s.handle(new ClientRequest.Unsubscribe(List.of(5L)), CHANNELS);
    assertEquals(-1, s.subscriptionFor(2));
  }

  @Test
  void subscriptionsAreCapped() {
    List<Channel> many = new ArrayList<>();
    for (int i = 1; i <= ClientSession.MAX_SUBSCRIPTIONS + 5; i++) {
      many.add(new Channel(i, "/t" + i, TopicKind.CLOCK));
    }
    ClientSession s = new ClientSession(false);
    int refused = 0;
    for (int i = 1; i <= ClientSession.MAX_SUBSCRIPTIONS + 5; i++) {
      if (s.handle(sub(i, i), many).problem() != null) {
        refused++;
      }
    }
    assertEquals(5, refused);
    assertEquals(ClientSession.MAX_SUBSCRIPTIONS, s.subscriptionCount());
  }

  @Test
  void removedChannelsLoseTheirSubscriptions() {
    ClientSession s = new ClientSession(false);
    s.handle(sub(3, 1), CHANNELS);
    s.channelsRemoved(List.of(CHANNELS.get(0)));
    assertEquals(-1, s.subscriptionFor(1));
  }

  @Test
  void aReadOnlySessionRefusesToTakeChannels() {
    ClientSession s = new ClientSession(false);
    ClientSession.Outcome o =
        s.handle(
            new ClientRequest.Advertise(
                List.of(new ClientRequest.ClientChannel(1, "/cmd_vel", "json", "Twist"))),
            CHANNELS);
    assertEquals(ClientSession.Problem.REFUSED, o.problem());
    assertTrue(o.replies().get(0).contains("--allow-control"), o.replies().toString());
    ClientSession.Outcome p =
        s.handle(new ClientRequest.Publish(1, new byte[] {'{', '}'}), CHANNELS);
    assertEquals(ClientSession.Problem.REFUSED, p.problem());
    assertNull(p.published());
  }

  @Test
  void aControllingSessionPublishesOnItsAdvertisedTopics() {
    ClientSession s = new ClientSession(true);
    assertNull(
        s.handle(
                new ClientRequest.Advertise(
                    List.of(new ClientRequest.ClientChannel(4, "/goal", "json", "Pose"))),
                CHANNELS)
            .problem());
    byte[] body = "{}".getBytes(StandardCharsets.UTF_8);
    ClientSession.Outcome o = s.handle(new ClientRequest.Publish(4, body), CHANNELS);
    assertEquals("/goal", o.published().topic());
    assertEquals(
        ClientSession.Problem.REFUSED,
        s.handle(
                new ClientRequest.Advertise(
                    List.of(new ClientRequest.ClientChannel(5, "/x", "cdr", "Pose"))),
                CHANNELS)
            .problem());
    s.handle(new ClientRequest.Unadvertise(List.of(4L)), CHANNELS);
    assertNull(s.handle(new ClientRequest.Publish(4, body), CHANNELS).published());
  }

  @Test
  void malformedAndUnknownAreSaidBackAndCounted() {
    ClientSession s = new ClientSession(false);
    ClientSession.Outcome m = s.handle(new ClientRequest.Malformed("bad"), CHANNELS);
    assertEquals(ClientSession.Problem.MALFORMED, m.problem());
    assertTrue(m.replies().get(0).contains("\"op\":\"status\""), m.replies().toString());
    assertEquals(
        ClientSession.Problem.UNKNOWN_OP,
        s.handle(new ClientRequest.Unknown("x"), CHANNELS).problem());
  }

  @Test
  void theFloodLimitAllowsABurstThenTheSteadyRate() {
    ClientSession s = new ClientSession(false);
    long t = 1_000_000_000L;
    int admitted = 0;
    for (int i = 0; i < 1000; i++) {
      if (s.admit(t)) {
        admitted++;
      }
    }
    assertEquals(ClientSession.BURST, admitted);
    assertFalse(s.admit(t));
    // one second later: PER_SECOND more
    t += 1_000_000_000L;
    admitted = 0;
    for (int i = 0; i < 1000; i++) {
      if (s.admit(t)) {
        admitted++;
      }
    }
    assertEquals(ClientSession.PER_SECOND, admitted);
  }
}
