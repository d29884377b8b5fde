package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.Futures;
import org.jaria.net.NetEncodable;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PublishedValue;
import org.jaria.net.server.ServerOptions;
import org.junit.jupiter.api.Test;

/** The client library: reconnecting, losing the server, and servers that misbehave. */
class ArClientBaseTest {

  @Test
  void subscriptionsAndHandlersSurviveAReconnect() throws Exception {
    PublishedValue v = new PublishedValue();
    AtomicLong last = new AtomicLong();
    try (ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).build());
        ArClientBase c = new ArClientBase("t")) {
      s.addPublishedData("v", "a value", "int", "", v);
      s.open();
      c.addHandler("v", p -> last.set(p.bufToLong()));
      CompletableFuture<?> granted = c.request("v", 50);
      c.connect("127.0.0.1", s.getPort(), "", "");
      Futures.get(granted);
      v.publish((NetEncodable) out -> out.intToBuf(1));
      Eventually.until("first value", () -> last.get() == 1);
      c.disconnect();
      assertFalse(c.isConnected());
      assertEquals(
          "disconnected by the client", c.getLastError(), "the reason is kept for the user");
      v.publish((NetEncodable) out -> out.intToBuf(2));
      c.connect("127.0.0.1", s.getPort(), "", "");
      Eventually.until("the value sent after reconnecting", () -> last.get() == 2);
      assertEquals(java.util.Map.of("v", 50L), c.getSubscriptions());
    }
  }

  @Test
  void losingTheServerIsReportedWithItsReason() throws Exception {
    CompletableFuture<String> reason = new CompletableFuture<>();
    ArServerBase s = new ArServerBase(ServerOptions.builder().port(0).build());
    s.open();
    try (ArClientBase c = new ArClientBase("t")) {
      c.addConnectionListener(
          new ConnectionListener() {
            @Override
            public void disconnected(ArClientBase client, String why) {
              reason.complete(why);
            }
          });
      c.connect("127.0.0.1", s.getPort(), "", "");
      s.close();
      assertEquals("closed by the server: the server is shutting down", Futures.get(reason));
      ArClientException e = Futures.failure(c.requestOnce("anything"));
      assertTrue(e.getMessage().startsWith("not connected"), e.getMessage());
    }
  }

  @Test
  void nobodyListeningOrNotAJariaServer() throws Exception {
    int freePort;
    try (ServerSocket ss = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      freePort = ss.getLocalPort();
    }
    try (ArClientBase c = new ArClientBase("t")) {
      ArClientException e =
          assertThrows(ArClientException.class, () -> c.connect("127.0.0.1", freePort, "", ""));
      assertTrue(
          e.getMessage().startsWith("cannot connect to 127.0.0.1:" + freePort), e.getMessage());
      assertFalse(c.blockingConnect("127.0.0.1", freePort, "", ""));
    }
    try (FakeServer http =
            new FakeServer(
                (in, out) ->
                    out.write(
                        "HTTP/1.0 400 Bad Request\r\n\r\n"
                            .getBytes(java.nio.charset.StandardCharsets.US_ASCII)));
        ArClientBase c = new ArClientBase("t")) {
      ArClientException e =
          assertThrows(ArClientException.class, () -> c.connect("127.0.0.1", http.port(), "", ""));
      assertEquals(NetError.MALFORMED, e.getCode());
      assertTrue(e.getMessage().startsWith("bad login reply"), e.getMessage());
    }
  }

  @Test
  void aServerSendingGarbageAfterLoginDisconnectsCleanly() throws Exception {
    Random rnd = new Random(23);
    for (int round = 0; round < 20; round++) {
      byte[] garbage = new byte[1 + rnd.nextInt(200)];
      rnd.nextBytes(garbage);
      if (round % 2 == 0 && garbage.length > 4) {
        java.nio.ByteBuffer.wrap(garbage).putInt(0, garbage.length - 4);
      }
      CompletableFuture<String> reason = new CompletableFuture<>();
      try (FakeServer bad =
              new FakeServer(
                  (in, out) -> {
                    welcome(in, out);
                    out.write(garbage);
                  });
          ArClientBase c = new ArClientBase("t")) {
        c.addConnectionListener(
            new ConnectionListener() {
              @Override
              public void disconnected(ArClientBase client, String why) {
                reason.complete(why);
              }
            });
        c.connect("127.0.0.1", bad.port(), "", "");
        String why = Futures.get(reason);
        assertFalse(why.isEmpty());
        assertFalse(c.isConnected(), "round " + round + ": " + why);
      }
    }
  }

  /** The server's side of a login with no password and an empty data list. */
  private static void welcome(DataInputStream in, OutputStream out) throws IOException {
    in.readFully(new byte[in.readInt()]);
    out.write(
        Frames.frame(
            Kind.CHALLENGE,
            Protocol.MAGIC,
            Protocol.VERSION,
            "fake",
            new byte[32],
            new byte[0],
            0));
    in.readFully(new byte[in.readInt()]);
    out.write(Frames.frame(Kind.WELCOME, ArNetPacket.of(1, 50, 65536, List.of())));
    out.flush();
  }

  /** A one-connection TCP server running a script. */
  private static final class FakeServer implements AutoCloseable {
    interface Script {
      void run(DataInputStream in, OutputStream out) throws IOException;
    }

    private final ServerSocket ss;
    private final Thread thread;

    FakeServer(Script script) throws IOException {
      ss = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
      thread =
          new Thread(
              () -> {
                try (Socket s = ss.accept()) {
                  s.setSoTimeout(10_000);
                  DataInputStream in = new DataInputStream(s.getInputStream());
                  script.run(in, s.getOutputStream());
                  s.getOutputStream().flush();
                  // Wait for the client to hang up.
                  while (in.read() >= 0) {
                    // discard
                  }
                } catch (IOException e) {
                  // The client went away: the script is over.
                }
              },
              "fake-server");
      thread.setDaemon(true);
      thread.start();
    }

    int port() {
      return ss.getLocalPort();
    }

    @Override
    public void close() throws IOException {
      ss.close();
      try {
        thread.join(10_000);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }
}
