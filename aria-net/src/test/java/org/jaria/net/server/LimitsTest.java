package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.clock.VirtualClock;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.NetEncodable;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.junit.jupiter.api.Test;

/**
 * One slow or hostile client cannot hurt the others: too many clients are refused, garbage and
 * oversized frames close only the sender, a client that stops reading is bounded then dropped,
 * silent clients time out.
 */
class LimitsTest {

  private static ServerOptions.Builder options() {
    return ServerOptions.builder().port(0).minInterval(Duration.ofMillis(20));
  }

  /** A server publishing a counter that the test bumps. */
  private static final class Rig implements AutoCloseable {
    final PublishedValue counter = new PublishedValue();
    final AtomicLong next = new AtomicLong();
    final ArServerBase server;

    Rig(ServerOptions o) throws Exception {
      server = new ArServerBase(o);
      server.addPublishedData("counter", "a number", "int", "", counter);
      server.addData(
          "big",
          "100 kB",
          "none",
          "bytes",
          "",
          Where.WORKER,
          (c, q, r) -> r.dataToBuf(new byte[100_000]));
      server.open();
    }

    long bump() {
      long v = next.incrementAndGet();
      counter.publish((NetEncodable) out -> out.intToBuf(v));
      return v;
    }

    /** A client subscribed to the counter, remembering the last value. */
    ArClientBase watcher(AtomicLong last) throws Exception {
      ArClientBase c = new ArClientBase("watcher");
      c.addHandler("counter", p -> last.set(p.bufToLong()));
      c.connect("127.0.0.1", server.getPort(), "", "");
      Futures.get(c.request("counter", 20));
      return c;
    }

    /** Bumps the counter and waits until {@code last} shows it. */
    void stillServed(AtomicLong last) {
      long v = bump();
      Eventually.until("the good client gets value " + v, () -> last.get() >= v);
    }

    @Override
    public void close() {
      server.close();
    }
  }

  @Test
  void theServerRefusesClientsBeyondItsMaximum() throws Exception {
    try (Rig rig = new Rig(options().maxClients(2).build());
        ArClientBase a = new ArClientBase("a");
        ArClientBase b = new ArClientBase("b");
        ArClientBase c = new ArClientBase("c")) {
      a.connect("127.0.0.1", rig.server.getPort(), "", "");
      b.connect("127.0.0.1", rig.server.getPort(), "", "");
      ArClientException e =
          assertThrows(
              ArClientException.class, () -> c.connect("127.0.0.1", rig.server.getPort(), "", ""));
      assertEquals(NetError.SERVER_FULL, e.getCode());
      assertTrue(e.getMessage().contains("maximum of 2 clients"), e.getMessage());
      assertEquals(1, rig.server.getStats().getRefusedFull());
      a.disconnect();
      Eventually.until("a's place freed", () -> rig.server.getClients().size() == 1);
      c.connect("127.0.0.1", rig.server.getPort(), "", "");
    }
  }

  @Test
  void garbageClosesOnlyTheClientThatSentIt() throws Exception {
    AtomicLong last = new AtomicLong();
    Random rnd = new Random(17);
    try (Rig rig = new Rig(options().build());
        ArClientBase good = rig.watcher(last)) {
      rig.stillServed(last);
      for (int round = 0; round < 40; round++) {
        try (RawClient bad = new RawClient(rig.server.getPort())) {
          if (round % 2 == 1) {
            bad.login("", null);
          }
          byte[] garbage = new byte[8 + rnd.nextInt(500)];
          rnd.nextBytes(garbage);
          // Half announce a length that fits, so the bytes reach the message decoder.
          if (round % 4 < 2) {
            ByteBuffer.wrap(garbage).putInt(0, garbage.length - 4);
          }
          bad.send(garbage);
          long code = bad.readUntilClosed();
          assertTrue(
              code == NetError.MALFORMED.code() || code == NetError.PROTOCOL.code() || code == -1,
              "round " + round + " closed with " + code);
        }
      }
      assertTrue(good.isConnected());
      rig.stillServed(last);
      assertEquals(40, rig.server.getStats().getMalformed());
      Eventually.until("only the good client left", () -> rig.server.getClients().size() == 1);
    }
  }

  @Test
  void anOversizedFrameIsRefusedBeforeItArrives() throws Exception {
    try (Rig rig = new Rig(options().maxInboundFrame(4096).build());
        RawClient bad = new RawClient(rig.server.getPort())) {
      bad.login("", null);
      bad.send(ByteBuffer.allocate(4).putInt(1 << 20).array());
      assertEquals(NetError.MALFORMED.code(), bad.readUntilClosed());
    }
  }

  @Test
  void aClientThatStopsReadingHasABoundedQueueAndIsDropped() throws Exception {
    AtomicLong last = new AtomicLong();
    try (Rig rig = new Rig(options().maxQueuedBytes(256 * 1024).socketSendBuffer(8192).build());
        ArClientBase good = rig.watcher(last);
        RawClient stuck = new RawClient(rig.server.getPort(), 4096)) {
      stuck.login("", null);
      int big =
          rig.server.dataList().stream()
              .filter(d -> d.name().equals("big"))
              .findFirst()
              .orElseThrow()
              .id();
      ArServerClient c = rig.server.getClients().get(1);
      // Ask for 100 kB again and again without reading a byte of the replies.
      for (int i = 0; i < 40 && !c.isClosed(); i++) {
        stuck.send(Kind.CALL, i, big);
        rig.stillServed(last);
        assertTrue(
            c.getOwnedQueuedBytes() <= 256 * 1024 + 100_100,
            "replies waiting stay under the limit: " + c.getOwnedQueuedBytes());
      }
      Eventually.until("the stuck client is dropped", c::isClosed);
      assertTrue(c.getCloseReason().contains("read faster"), c.getCloseReason());
      assertEquals(1, rig.server.getStats().getDroppedSlow());
      assertEquals(0, c.getQueuedBytes(), "its queue is released");
      rig.stillServed(last);
      assertTrue(good.isConnected());
    }
  }

  @Test
  void aClientWhoseSocketStallsIsDroppedAfterTheStallTimeout() throws Exception {
    VirtualClock clock = new VirtualClock();
    PublishedValue video = new PublishedValue();
    try (Rig rig =
            new Rig(
                options()
                    .timeoutClock(clock)
                    .stallTimeout(Duration.ofSeconds(10))
                    .idleTimeout(Duration.ZERO)
                    .socketSendBuffer(8192)
                    .build());
        RawClient stuck = new RawClient(rig.server.getPort(), 4096)) {
      rig.server.addPublishedData("video", "frames", "bytes", "", video);
      stuck.login("", null);
      stuck.send(Kind.SUBSCRIBE, 1, rig.server.dataList().size(), 20);
      ArServerClient c = rig.server.getClients().get(0);
      byte[] frame = new byte[500_000];
      video.publish(out -> out.dataToBuf(frame));
      Eventually.until("writing has begun", () -> c.getBytesSent() > 0);
      // Until the socket is full each write is progress; once it is, the next 11 s of silence
      // (on the server's clock) drop the client.
      Eventually.until(
          "the stalled client is dropped",
          () -> {
            clock.advance(Duration.ofSeconds(11));
            return c.isClosed();
          });
      assertTrue(c.getBytesSent() < 500_000, "it had not taken the frame");
      assertTrue(c.getCloseReason().contains("took no data"), c.getCloseReason());
    }
  }

  @Test
  void aSilentClientIsDroppedAfterTheIdleTimeout() throws Exception {
    VirtualClock clock = new VirtualClock();
    try (Rig rig =
            new Rig(options().timeoutClock(clock).idleTimeout(Duration.ofSeconds(30)).build());
        RawClient quiet = new RawClient(rig.server.getPort())) {
      quiet.login("", null);
      clock.advance(Duration.ofSeconds(20));
      quiet.send(Kind.PING, 1);
      quiet.readUntil(Kind.PONG);
      clock.advance(Duration.ofSeconds(20));
      quiet.send(Kind.PING, 2);
      assertEquals(2, quiet.readUntil(Kind.PONG).body().bufToLong(), "pings keep it alive");
      clock.advance(Duration.ofSeconds(31));
      assertEquals(NetError.IDLE.code(), quiet.readUntilClosed());
      assertEquals(1, rig.server.getStats().getDroppedIdle());
    }
  }

  @Test
  void goodbyeClosesTheConnectionWithItsReason() throws Exception {
    try (Rig rig = new Rig(options().build());
        RawClient raw = new RawClient(rig.server.getPort())) {
      raw.login("", null);
      ArServerClient c = rig.server.getClients().get(0);
      raw.send(Kind.BYE);
      assertEquals(-1, raw.readUntilClosed());
      Eventually.until("closed", c::isClosed);
      assertEquals("the client said goodbye", c.getCloseReason());
    }
  }

  @Test
  void closingTheServerTellsClientsWhy() throws Exception {
    Rig rig = new Rig(options().build());
    try (RawClient raw = new RawClient(rig.server.getPort())) {
      raw.login("", null);
      rig.close();
      assertEquals(NetError.SHUTTING_DOWN.code(), raw.readUntilClosed());
    }
    assertTrue(!rig.server.isOpen());
  }
}
