package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.NetEncodable;
import org.jaria.net.RawClient;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;

/**
 * ArNetworking's requests at the packet level: once, at an interval (capped at the server's
 * minimum, only new versions), stop, unknown numbers, busy, and a late reader that gets the newest
 * value rather than a backlog.
 */
class RequestsTest {

  private static ArServerBase server(ServerOptions.Builder o) throws Exception {
    ArServerBase s = new ArServerBase(o.port(0).udp(false).build());
    return s;
  }

  /** Data "slow", whose handler holds a worker until {@code release} and then answers "done". */
  private static void addSlowData(ArServerBase s, CountDownLatch release) {
    s.addData(
        "slow",
        "",
        "none",
        "string",
        "",
        Where.WORKER,
        (c, q, r) -> {
          release.await(20, TimeUnit.SECONDS);
          r.strToBuf("done");
        });
  }

  /** Reads a JAria requestFailed packet: data name, why, code. */
  private static NetError failure(RawClient raw) throws Exception {
    ArNetPacket p = raw.readUntil(Protocol.FIRST_DATA_COMMAND);
    p.bufToStr();
    p.bufToStr();
    return NetError.fromCode(p.bufToByte2());
  }

  @Test
  void aPublishedValueAtAnIntervalOnlyWhenNewAndNeverFasterThanTheMinimum() throws Exception {
    PublishedValue v = new PublishedValue();
    try (ArServerBase s = server(ServerOptions.builder().minInterval(Duration.ofMillis(200)))) {
      s.addPublishedData("v", "a number", "byte8", "", v);
      s.open();
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.login("", "");
        int cmd = s.findCommandFromName("v");
        v.publish((NetEncodable) out -> out.byte8ToBuf(1));
        raw.request(cmd, 1); // asks for 1 ms: gets 200 ms
        assertEquals(1, raw.readUntil(cmd).bufToByte8(), "the current value at once");
        Eventually.until(
            "granted the minimum",
            () -> s.getClients().get(0).getSubscriptions().get("v").equals(Duration.ofMillis(200)));
        long t = System.nanoTime();
        v.publish((NetEncodable) out -> out.byte8ToBuf(2));
        assertEquals(2, raw.readUntil(cmd).bufToByte8());
        v.publish((NetEncodable) out -> out.byte8ToBuf(3));
        assertEquals(3, raw.readUntil(cmd).bufToByte8(), "only new versions are sent");
        assertTrue(System.nanoTime() - t >= TimeUnit.MILLISECONDS.toNanos(150), "not faster");
        ArNetPacket stop = new ArNetPacket(Protocol.CLIENT_REQUEST_STOP);
        stop.uByte2ToBuf(cmd);
        raw.send(stop);
        Eventually.until("stopped", () -> s.getClients().get(0).getSubscriptions().isEmpty());
      }
    }
  }

  @Test
  void unknownNumbersAreIgnoredAndTheConnectionStays() throws Exception {
    try (ArServerBase s = server(ServerOptions.builder())) {
      s.addData(
          "echo", "", "string", "string", "", Where.WORKER, (c, q, r) -> r.strToBuf(q.bufToStr()));
      s.open();
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.login("", "");
        raw.requestOnce(60_000, new ArNetPacket());
        raw.request(60_001, 100);
        ArNetPacket arg = new ArNetPacket();
        arg.strToBuf("still here");
        raw.requestOnce(s.findCommandFromName("echo"), arg);
        assertEquals("still here", raw.readUntil(s.findCommandFromName("echo")).bufToStr());
        assertEquals(2, s.getStats().getRequestErrors());
        // A malformed argument is a failed request, not a closed connection.
        raw.requestOnce(s.findCommandFromName("echo"), ArNetPacket.wrap(new byte[] {'x'}));
        assertEquals(NetError.BAD_ARGUMENTS, failure(raw));
      }
    }
  }

  @Test
  void tooManyRequestsWaitingAreRefusedAsBusy() throws Exception {
    CountDownLatch release = new CountDownLatch(1);
    try (ArServerBase s =
        server(ServerOptions.builder().maxPendingCalls(2).workerThreads(1).workerQueue(8))) {
      addSlowData(s, release);
      s.open();
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.login("", "");
        int cmd = s.findCommandFromName("slow");
        for (int i = 0; i < 3; i++) {
          raw.requestOnce(cmd, new ArNetPacket());
        }
        assertEquals(NetError.BUSY, failure(raw));
        release.countDown();
        assertEquals("done", raw.readUntil(cmd).bufToStr());
        assertEquals("done", raw.readUntil(cmd).bufToStr());
        assertEquals(1, s.getStats().getBusy());
      }
    }
  }

  /**
   * A monitor asks for everything it shows when it connects (JAria's monitor sends some 25 requests
   * at once, MobileEyes as many): with the default options, none is refused as busy even while the
   * server's workers are all held up.
   */
  @Test
  void aConnectingMonitorsBurstOfRequestsIsNotRefused() throws Exception {
    CountDownLatch release = new CountDownLatch(1);
    try (ArServerBase s = server(ServerOptions.builder())) {
      addSlowData(s, release);
      s.open();
      try (RawClient raw = new RawClient(s.getPort())) {
        raw.login("", "");
        int cmd = s.findCommandFromName("slow");
        long before = s.getStats().getRequests();
        int burst = 40;
        for (int i = 0; i < burst; i++) {
          raw.requestOnce(cmd, new ArNetPacket());
        }
        Eventually.until(
            "the burst read while the workers wait",
            () -> s.getStats().getRequests() >= before + burst);
        assertEquals(0, s.getStats().getBusy(), "refused as busy");
        release.countDown();
        for (int i = 0; i < burst; i++) {
          assertEquals("done", raw.readUntil(cmd).bufToStr());
        }
      }
    }
  }

  @Test
  void aClientThatReadsLateGetsTheNewestValueNotABacklog() throws Exception {
    byte[] payload = new byte[30_000];
    PublishedValue big = new PublishedValue();
    try (ArServerBase s = server(ServerOptions.builder().minInterval(Duration.ofMillis(20)))) {
      s.addPublishedData("big", "large", "data", "", big);
      s.open();
      try (RawClient raw = new RawClient(s.getPort(), 4096)) {
        raw.login("", "");
        int cmd = s.findCommandFromName("big");
        raw.request(cmd, 20);
        ArServerClient c = s.getClients().get(0);
        Eventually.until("the request arrived", () -> c.requests.containsKey(cmd));
        ArServerClient.Request r = c.requests.get(cmd);
        for (int v = 1; v <= 100; v++) {
          long version = v;
          big.publish(
              out -> {
                out.byte8ToBuf(version);
                out.dataToBuf(payload, 0, payload.length - 8);
              });
          long published = big.current().version();
          // The server has taken this version for the client (queued, or replacing a waiting one).
          Eventually.until("version " + version + " taken", () -> r.lastVersion == published);
        }
        assertTrue(
            c.getCoalescedCount() > 0, "updates were replaced while the client did not read");
        assertTrue(
            c.getPeakQueuedBytes() <= 3L * (payload.length + 100),
            "only a few updates ever wait: " + c.getPeakQueuedBytes());
        long last = 0;
        while (last < 100) {
          long version = raw.readUntil(cmd).bufToByte8();
          assertTrue(version >= last, "versions never go back: " + version + " after " + last);
          last = version;
        }
        assertEquals(100, last, "the newest value arrives");
      }
    }
  }
}
