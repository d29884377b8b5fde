package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * One slow or hostile client cannot hurt the others: too many clients are refused, garbage and bad
 * lengths close only the sender, sockets that never log in cannot take every slot, a client that
 * stops reading is bounded then dropped, silent clients time out when asked to.
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
      server.addPublishedData("counter", "a number", "byte8", "", counter);
      server.addData(
          "big",
          "100 kB",
          "none",
          "bytes",
          "",
          Where.WORKER,
          (c, q, r) -> r.dataToBuf(new byte[30_000]));
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
      assertTrue(e.getMessage().contains("maximum of clients"), e.getMessage());
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
          } else {
            bad.readIntroduction();
          }
          byte[] garbage = new byte[8 + rnd.nextInt(500)];
          rnd.nextBytes(garbage);
          // Half start like a packet with a length that fits, so the checksum must catch them.
          if (round % 4 < 2) {
            garbage[0] = 0x0f;
            garbage[1] = 0x0c;
            garbage[2] = (byte) garbage.length;
            garbage[3] = (byte) (garbage.length >> 8);
          }
          bad.send(garbage);
          long code = bad.readUntilClosed();
          assertTrue(
              code == Protocol.SERVER_SHUTDOWN || code == -1, "round " + round + ": " + code);
        }
      }
      assertTrue(good.isConnected());
      rig.stillServed(last);
      assertEquals(40, rig.server.getStats().getMalformed());
      Eventually.until("only the good client left", () -> rig.server.getClients().size() == 1);
    }
  }

  @Test
  void aLengthBeyondArNetworkingsLimitIsRefusedBeforeItArrives() throws Exception {
    try (Rig rig = new Rig(options().build());
        RawClient bad = new RawClient(rig.server.getPort())) {
      bad.login("", null);
      // 0x0f 0x0c then 65000 as the length: more than 32000, refused at once.
      bad.send(new byte[] {0x0f, 0x0c, (byte) 0xe8, (byte) 0xfd});
      assertEquals(Protocol.SERVER_SHUTDOWN, bad.readUntilClosed());
      assertEquals(1, rig.server.getStats().getMalformed());
    }
  }

  @Test
  void socketsThatNeverLogInCannotTakeEverySlot() throws Exception {
    try (Rig rig = new Rig(options().maxPendingLogins(3).maxPendingLoginsPerAddress(3).build())) {
      java.util.List<RawClient> idle = new java.util.ArrayList<>();
      try {
        for (int i = 0; i < 3; i++) {
          RawClient r = new RawClient(rig.server.getPort());
          r.readIntroduction();
          idle.add(r);
        }
        // A fourth from the same address takes the place of the oldest, which is closed.
        try (RawClient fourth = new RawClient(rig.server.getPort())) {
          fourth.readIntroduction();
          assertEquals(-1, idle.remove(0).readUntilClosed(), "the oldest idle socket is closed");
          assertEquals(1, rig.server.getStats().getReplacedPending());
          // And a real user gets in with every slot taken by sockets that never log in.
          try (ArClientBase real = new ArClientBase("real")) {
            real.connect("127.0.0.1", rig.server.getPort(), "", "");
            assertTrue(real.isConnected());
          }
        }
      } finally {
        for (RawClient r : idle) {
          r.close();
        }
      }
    }
  }

  @Test
  void aClientThatStopsReadingHasABoundedQueueAndIsDropped() throws Exception {
    AtomicLong last = new AtomicLong();
    try (Rig rig = new Rig(options().maxQueuedBytes(256 * 1024).socketSendBuffer(8192).build());
        ArClientBase good = rig.watcher(last);
        RawClient stuck = new RawClient(rig.server.getPort(), 4096)) {
      stuck.login("", null);
      int big = rig.server.findCommandFromName("big");
      ArServerClient c = rig.server.getClients().get(1);
      // Ask for 30 kB again and again without reading a byte of the replies.
      for (int i = 0; i < 200 && !c.isClosed(); i++) {
        stuck.requestOnce(big, new org.jaria.net.ArNetPacket());
        if (i % 10 == 0) {
          rig.stillServed(last);
        }
        assertTrue(
            c.getOwnedQueuedBytes() <= 256 * 1024 + 30_100,
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
      stuck.request(rig.server.findCommandFromName("video"), 20);
      ArServerClient c = rig.server.getClients().get(0);
      // A new frame of 30 kB at every look, until the socket is full; once it is, the next 11 s
      // of silence (on the server's clock) drop the client.
      AtomicLong n = new AtomicLong();
      Eventually.until(
          "the stalled client is dropped",
          () -> {
            byte[] frame = new byte[30_000];
            frame[0] = (byte) n.incrementAndGet();
            video.publish(out -> out.dataToBuf(frame));
            clock.advance(Duration.ofSeconds(11));
            return c.isClosed();
          });
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
      int counter = rig.server.findCommandFromName("counter");
      rig.bump();
      clock.advance(Duration.ofSeconds(20));
      // Anything the client sends keeps it alive (ArNetworking has no ping).
      quiet.requestOnce(counter, new org.jaria.net.ArNetPacket());
      quiet.readUntil(counter);
      clock.advance(Duration.ofSeconds(20));
      quiet.requestOnce(counter, new org.jaria.net.ArNetPacket());
      quiet.readUntil(counter);
      clock.advance(Duration.ofSeconds(31));
      assertEquals(Protocol.SERVER_SHUTDOWN, quiet.readUntilClosed());
      assertEquals(1, rig.server.getStats().getDroppedIdle());
    }
  }

  @Test
  void goodbyeClosesTheConnectionWithItsReason() throws Exception {
    try (Rig rig = new Rig(options().build());
        RawClient raw = new RawClient(rig.server.getPort())) {
      raw.login("", null);
      ArServerClient c = rig.server.getClients().get(0);
      raw.send(new org.jaria.net.ArNetPacket(Protocol.CLIENT_SHUTDOWN));
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
      assertEquals(Protocol.SERVER_SHUTDOWN, raw.readUntilClosed());
    }
    assertTrue(!rig.server.isOpen());
  }
}
