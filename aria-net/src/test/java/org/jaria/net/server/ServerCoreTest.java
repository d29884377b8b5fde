package org.jaria.net.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.net.ArNetPacket;
import org.jaria.net.client.ArClientBase;
import org.junit.jupiter.api.Test;

class ServerCoreTest {

  @Test
  void callAndSubscribe() throws Exception {
    PublishedValue counter = new PublishedValue();
    try (ArServerBase server = new ArServerBase(ServerOptions.builder().port(0).build())) {
      server.addData(
          "echo",
          "echoes",
          "string",
          "string",
          "",
          Where.WORKER,
          (c, req, reply) -> reply.strToBuf("echo:" + req.bufToStr()));
      server.addPublishedData("counter", "a number", "int", "", counter);
      server.open();
      try (ArClientBase client = new ArClientBase("t")) {
        client.connect("127.0.0.1", server.getPort(), "", "");
        assertEquals(
            "echo:hi", client.requestOnce("echo", "hi").get(5, TimeUnit.SECONDS).bufToStr());
        CountDownLatch got = new CountDownLatch(1);
        AtomicInteger last = new AtomicInteger();
        client.addHandler(
            "counter",
            p -> {
              last.set(p.bufToInt());
              if (last.get() == 3) {
                got.countDown();
              }
            });
        assertEquals(Duration.ofMillis(50), client.request("counter", 10).get(5, TimeUnit.SECONDS));
        counter.publish(out -> out.intToBuf(1));
        counter.publish(out -> out.intToBuf(3));
        assertTrue(got.await(5, TimeUnit.SECONDS));
        assertEquals(1, server.getNumClients());
      }
    }
  }

  @Test
  void packetRoundTrip() {
    ArNetPacket p = ArNetPacket.of(1, -70000L, 2.5, "x", true, null, new byte[] {1, 2});
    ArNetPacket r = p.toReader();
    assertEquals(1, r.bufToInt());
    assertEquals(-70000L, r.bufToLong());
    assertEquals(2.5, r.bufToDouble());
    assertEquals("x", r.bufToStr());
    assertTrue(r.bufToBool());
    assertTrue(r.bufToNil());
    assertEquals(2, r.bufToData().length);
    assertFalse(r.hasMore());
  }
}
