package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.protocol.Kind;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Published data at a rate: only new versions are sent, unsubscribing stops them. */
class SubscriptionTest {

  private final PublishedValue counter = new PublishedValue();
  private final PublishedValue marker = new PublishedValue();
  private final List<Long> seen = Collections.synchronizedList(new ArrayList<>());
  private final List<Long> markers = Collections.synchronizedList(new ArrayList<>());
  private ArServerBase server;
  private ArClientBase client;

  @BeforeEach
  void open() throws Exception {
    server =
        new ArServerBase(
            ServerOptions.builder().port(0).minInterval(Duration.ofMillis(20)).build());
    server.addPublishedData("counter", "a number", "int", "", counter);
    server.addPublishedData("marker", "another", "int", "", marker);
    server.open();
    client = new ArClientBase("t");
    client.addHandler("counter", p -> seen.add(p.bufToLong()));
    client.addHandler("marker", p -> markers.add(p.bufToLong()));
    client.connect("127.0.0.1", server.getPort(), "", "");
  }

  @AfterEach
  void close() {
    client.close();
    server.close();
  }

  private static NetValue value(long v) {
    return new NetValue(v);
  }

  /** A published number. */
  private record NetValue(long v) implements org.jaria.net.NetEncodable {
    @Override
    public void write(ArNetPacket out) {
      out.intToBuf(v);
    }
  }

  @Test
  void theRateIsCappedAtTheServersMinimum() throws Exception {
    assertEquals(Duration.ofMillis(20), Futures.get(client.request("counter", 1)));
    assertEquals(Duration.ofMillis(500), Futures.get(client.request("counter", 500)));
    assertEquals(
        Duration.ofMillis(500), server.getClients().get(0).getSubscriptions().get("counter"));
  }

  @Test
  void onlyNewVersionsAreSent() throws Exception {
    Futures.get(client.request("counter", 20));
    counter.publish(value(1));
    Eventually.until("first value", () -> seen.contains(1L));
    counter.publishIfChanged(value(1));
    counter.publish(value(2));
    Eventually.until("second value", () -> seen.contains(2L));
    assertEquals(List.of(1L, 2L), seen, "no repeats of a version already sent");
    assertEquals(2, client.getUpdatesReceived());
  }

  @Test
  void subscribingGetsTheCurrentValueAtOnce() throws Exception {
    counter.publish(value(41));
    Futures.get(client.request("counter", 60_000));
    Eventually.until("the current value", () -> seen.contains(41L));
  }

  @Test
  void unsubscribingStopsUpdates() throws Exception {
    Futures.get(client.request("counter", 20));
    Futures.get(client.request("marker", 20));
    counter.publish(value(1));
    Eventually.until("first value", () -> seen.contains(1L));
    client.requestStop("counter");
    Futures.get(client.ping()); // the server has handled the UNSUBSCRIBE before the PING
    counter.publish(value(2));
    marker.publish(value(1));
    Eventually.until("the marker", () -> markers.contains(1L));
    assertEquals(List.of(1L), seen);
    assertEquals(
        List.of("marker"), List.copyOf(server.getClients().get(0).getSubscriptions().keySet()));
  }

  @Test
  void aClientThatReadsLateGetsTheNewestVersionNotABacklog() throws Exception {
    byte[] payload = new byte[200_000];
    PublishedValue big = new PublishedValue();
    server.addPublishedData("big", "large", "bytes", "", big);
    // A new data entry is only listed for clients that log in after it exists.
    try (RawClient raw = new RawClient(server.getPort(), 4096)) {
      raw.login("", null);
      int id = server.dataList().size();
      raw.send(Kind.SUBSCRIBE, 1, id, 20);
      ArServerClient c = server.getClients().get(server.getClients().size() - 1);
      for (int v = 1; v <= 100; v++) {
        int version = v;
        big.publish(out -> out.dataToBuf(payload));
        Eventually.until(
            "update " + version + " queued or coalesced",
            () -> server.getStats().getUpdatesQueued() >= version);
      }
      assertTrue(c.getCoalescedCount() > 0, "updates were replaced while the client did not read");
      assertTrue(
          c.getPeakQueuedBytes() <= 2L * (payload.length + 1000),
          "at most the update being written and one waiting: " + c.getPeakQueuedBytes());
      long last = 0;
      while (last < 100) {
        RawClient.Frame f = raw.readUntil(Kind.UPDATE);
        assertEquals(id, f.body().bufToInt());
        long version = f.body().bufToLong();
        assertTrue(version >= last, "versions never go back: " + version + " after " + last);
        last = version;
      }
      assertEquals(100, last, "the newest version arrives");
    }
  }
}
