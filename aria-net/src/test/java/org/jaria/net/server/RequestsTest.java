package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Futures;
import org.jaria.net.RawClient;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Requests answered once: replies, errors that name the problem, large replies in parts. */
class RequestsTest {

  private static final byte[] BIG = new byte[300_000];

  static {
    new Random(1).nextBytes(BIG);
  }

  private final CountDownLatch release = new CountDownLatch(1);
  private ArServerBase server;
  private ArClientBase client;

  @BeforeEach
  void open() throws Exception {
    server = new ArServerBase(ServerOptions.builder().port(0).maxPendingCalls(2).build());
    server.addData(
        "echo",
        "echoes",
        "string",
        "string",
        "",
        Where.WORKER,
        (c, q, r) -> r.strToBuf("echo:" + q.bufToStr()));
    server.addData(
        "big", "300 kB", "none", "bytes", "", Where.WORKER, (c, q, r) -> r.dataToBuf(BIG));
    server.addData(
        "fails",
        "throws",
        "none",
        "none",
        "",
        Where.CYCLE,
        (c, q, r) -> {
          throw new IllegalStateException("the gripper is not there");
        });
    server.addData(
        "refuses",
        "answers with a code",
        "none",
        "none",
        "",
        Where.WORKER,
        (c, q, r) -> {
          throw new NetRequestException(NetError.UNAVAILABLE, "no camera on this robot");
        });
    server.addData(
        "waits",
        "blocks until the test releases it",
        "none",
        "none",
        "",
        Where.WORKER,
        (c, q, r) -> release.await(20, TimeUnit.SECONDS));
    server.addPublishedData("value", "a value", "int", "", new PublishedValue());
    server.open();
    client = new ArClientBase("t");
    client.connect("127.0.0.1", server.getPort(), "", "");
  }

  @AfterEach
  void close() {
    release.countDown();
    client.close();
    server.close();
  }

  private int id(String name) {
    return server.dataList().stream()
        .filter(d -> d.name().equals(name))
        .findFirst()
        .orElseThrow()
        .id();
  }

  @Test
  void requestAndResponse() throws Exception {
    assertEquals("echo:hi", Futures.get(client.requestOnce("echo", "hi")).bufToStr());
    assertEquals(1, server.getStats().getRequests());
  }

  @Test
  void theDataListIsWhatTheServerRegistered() {
    List<DataInfo> seen = client.getDataList();
    assertEquals(server.dataList(), seen);
    assertEquals(Protocol.FIRST_DATA_ID, seen.get(0).id());
    assertTrue(
        seen.stream().filter(DataInfo::subscribable).allMatch(d -> d.name().equals("value")));
  }

  @Test
  void errorsNameTheProblemAndKeepTheConnection() throws Exception {
    var bad = Futures.failure(client.requestOnce("echo", 42));
    assertEquals(NetError.BAD_ARGUMENTS, bad.getCode());
    assertEquals("echo: expected a string as value 1 but found integer", bad.getMessage());
    var failed = Futures.failure(client.requestOnce("fails"));
    assertEquals(NetError.FAILED, failed.getCode());
    assertTrue(failed.getMessage().contains("the gripper is not there"), failed.getMessage());
    var refused = Futures.failure(client.requestOnce("refuses"));
    assertEquals(NetError.UNAVAILABLE, refused.getCode());
    assertEquals("no camera on this robot", refused.getMessage());
    var none = Futures.failure(client.requestOnce("value"));
    assertEquals(NetError.UNAVAILABLE, none.getCode(), "published data with no value yet");
    assertTrue(client.isConnected());
    assertEquals("echo:still", Futures.get(client.requestOnce("echo", "still")).bufToStr());
  }

  @Test
  void unknownDataByNumber() throws Exception {
    try (RawClient raw = new RawClient(server.getPort())) {
      raw.login("", null);
      raw.send(Kind.CALL, 5, 999);
      ArNetPacket e = raw.readUntil(Kind.ERROR).body();
      assertEquals(5, e.bufToInt());
      assertEquals(999, e.bufToInt());
      assertEquals(NetError.UNKNOWN_DATA.code(), e.bufToLong());
      raw.send(Kind.PING, 77);
      assertEquals(77, raw.readUntil(Kind.PONG).body().bufToLong(), "still connected");
    }
  }

  @Test
  void largeRepliesTravelInPartsAndComeBackWhole() throws Exception {
    assertArrayEquals(BIG, Futures.get(client.requestOnce("big")).bufToData());
    try (RawClient raw = new RawClient(server.getPort())) {
      raw.login("", null);
      raw.send(Kind.CALL, 9, id("big"));
      int parts = 0;
      int bytes = 0;
      boolean last = false;
      while (!last) {
        ArNetPacket p = raw.readUntil(Kind.RESPONSE).body();
        assertEquals(9, p.bufToInt());
        assertEquals(id("big"), p.bufToInt());
        last = p.bufToBool();
        int part = p.getRemaining();
        assertTrue(part <= Protocol.PART_SIZE);
        bytes += part;
        parts++;
      }
      assertEquals(ArNetPacket.of((Object) BIG).getLength(), bytes);
      assertEquals(5, parts, "300 kB in parts of 60 kiB");
    }
  }

  @Test
  void tooManyRequestsWaitingAreRefusedAsBusy() throws Exception {
    var a = client.requestOnce("waits");
    var b = client.requestOnce("waits");
    var busy = Futures.failure(client.requestOnce("waits"));
    assertEquals(NetError.BUSY, busy.getCode());
    assertTrue(busy.getMessage().contains("more than 2 requests waiting"), busy.getMessage());
    release.countDown();
    Futures.get(a);
    Futures.get(b);
    assertEquals("echo:x", Futures.get(client.requestOnce("echo", "x")).bufToStr());
    assertEquals(1, server.getStats().getBusy());
  }

  @Test
  void requestsCannotBeSubscribedTo() {
    var e = Futures.failure(client.request("echo", 100));
    assertEquals(NetError.NOT_SUBSCRIBABLE, e.getCode());
    var unknown = Futures.failure(client.request("nothing", 100));
    assertEquals(NetError.UNKNOWN_DATA, unknown.getCode());
  }

  @Test
  void pingMeasuresTheRoundTrip() throws Exception {
    assertFalse(Futures.get(client.ping()).isNegative());
  }
}
