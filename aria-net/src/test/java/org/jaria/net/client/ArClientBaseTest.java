package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.NetEncodable;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PublishedValue;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.Where;
import org.junit.jupiter.api.Test;

/** The client library against a JAria server, a dead port and a server that is not one. */
class ArClientBaseTest {

  private static ArServerBase server(PublishedValue counter) throws Exception {
    ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).build());
    s.addPublishedData("counter", "a number", "byte8", "", counter);
    s.addData(
        "add",
        "adds two byte4",
        "byte4: a; byte4: b",
        "byte4: sum",
        "",
        Where.WORKER,
        (c, q, r) -> r.byte4ToBuf(q.bufToByte4() + q.bufToByte4()));
    s.open();
    return s;
  }

  @Test
  void requestsOnceAndAtAnIntervalSurviveAReconnect() throws Exception {
    PublishedValue counter = new PublishedValue();
    AtomicLong last = new AtomicLong();
    try (ArClientBase c = new ArClientBase("c")) {
      c.addHandler("counter", p -> last.set(p.bufToByte8()));
      int port;
      try (ArServerBase s = server(counter)) {
        port = s.getPort();
        c.connect("127.0.0.1", port, "", "");
        assertEquals(7, Futures.get(c.requestOnce("add", 3, 4)).bufToByte4());
        Futures.get(c.request("counter", 20));
        counter.publish((NetEncodable) out -> out.byte8ToBuf(1));
        Eventually.until("value 1", () -> last.get() == 1);
      }
      Eventually.until("the loss is noticed", () -> !c.isConnected());
      assertTrue(c.getLastError().contains("shut"), c.getLastError());
      PublishedValue again = new PublishedValue();
      try (ArServerBase s = new ArServerBase(ServerOptions.builder().port(port).build())) {
        s.addPublishedData("counter", "a number", "byte8", "", again);
        s.open();
        c.connect("127.0.0.1", port, "", "");
        again.publish((NetEncodable) out -> out.byte8ToBuf(2));
        Eventually.until("the request was sent again", () -> last.get() == 2);
      }
    }
  }

  @Test
  void nobodyListeningOrNotAnArNetworkingServer() throws Exception {
    int free;
    try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      free = probe.getLocalPort();
    }
    try (ArClientBase c =
        new ArClientBase(
            new ClientOptions("c", Duration.ofMillis(500), Duration.ofSeconds(1), ""))) {
      ArClientException e =
          assertThrows(ArClientException.class, () -> c.connect("127.0.0.1", free, "", ""));
      assertTrue(e.getMessage().contains("is the server running"), e.getMessage());
      try (ServerSocket http = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
        AtomicReference<Exception> failed = new AtomicReference<>();
        Thread t =
            new Thread(
                () -> {
                  try (Socket s = http.accept()) {
                    OutputStream o = s.getOutputStream();
                    o.write(
                        "HTTP/1.0 200 OK\r\n\r\n"
                            .getBytes(java.nio.charset.StandardCharsets.US_ASCII));
                    o.flush();
                    s.getInputStream().read();
                  } catch (Exception ex) {
                    failed.set(ex);
                  }
                },
                "test-http");
        t.start();
        ArClientException notAria =
            assertThrows(
                ArClientException.class, () -> c.connect("127.0.0.1", http.getLocalPort(), "", ""));
        assertTrue(notAria.getMessage().contains("not ArNetworking"), notAria.getMessage());
        t.join(5000);
      }
      assertFalse(c.isConnected());
    }
  }
}
