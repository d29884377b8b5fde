package org.jaria.net.client;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.jaria.net.ArNetPacket;
import org.jaria.net.protocol.Protocol;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A server that sends its introduction one byte at a time, each byte well within the connect
 * timeout, must not hold the client for longer than that timeout in all: the login has one
 * deadline, not one per read. (Before, such a server kept {@code connect} waiting for ever.)
 */
@Timeout(60)
class LoginDeadlineTest {

  @Test
  void aTricklingServerCannotStretchTheLogin() throws Exception {
    ArNetPacket intro = new ArNetPacket(Protocol.SERVER_INTRODUCTION);
    intro.strToBuf(
        "a very long version string that takes the server a long time to send".repeat(20));
    byte[] wire = intro.toWire();
    try (ServerSocket trickler = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      Thread t =
          new Thread(
              () -> {
                try (Socket s = trickler.accept()) {
                  OutputStream out = s.getOutputStream();
                  for (byte b : wire) {
                    out.write(b);
                    out.flush();
                    // Paced, not synchronised: one byte every 50 ms (1.4 kB takes over a minute).
                    LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(50));
                  }
                } catch (Exception e) {
                  // the client gave up, as it should
                }
              },
              "test-trickler");
      t.setDaemon(true);
      t.start();
      ClientOptions o =
          new ClientOptions("patient", Duration.ofMillis(400), Duration.ofSeconds(1), "");
      try (ArClientBase c = new ArClientBase(o)) {
        ArClientException e =
            assertThrows(
                ArClientException.class,
                () -> c.connect("127.0.0.1", trickler.getLocalPort(), "", ""));
        assertTrue(e.getMessage().contains("no login answer"), e.getMessage());
        assertFalse(c.isConnected());
      }
    }
  }
}
