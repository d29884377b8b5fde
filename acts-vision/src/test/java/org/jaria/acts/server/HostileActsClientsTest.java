package org.jaria.acts.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.StillImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.clock.Clock;
import org.jaria.clock.VirtualClock;
import org.junit.jupiter.api.Test;

/**
 * Hostile clients on the ACTS port (loopback, a bounded number of sockets): connections that never
 * say a word must neither keep the server full nor stay for ever.
 */
class HostileActsClientsTest {

  private static ActsServer start(ServerSettings s) throws Exception {
    return start(s, Clock.system());
  }

  private static ActsServer start(ServerSettings s, Clock clock) throws Exception {
    ActsServer srv =
        new ActsServer(
            new VisionPipeline(
                new StillImageSource(TestScene.render(160, 120)),
                new ChannelBank(),
                TrackerSettings.DEFAULT),
            s.withAddress("127.0.0.1", 0),
            clock);
    srv.start();
    assertTrue(srv.awaitFrames(1, 10, TimeUnit.SECONDS));
    return srv;
  }

  private static Socket connect(ActsServer srv) throws IOException {
    Socket s = new Socket(InetAddress.getLoopbackAddress(), srv.getPort());
    s.setSoTimeout(5000);
    return s;
  }

  /** Reads until end of stream (bounded by the socket timeout); true if the server closed it. */
  private static boolean closedByServer(Socket s) {
    try {
      InputStream in = s.getInputStream();
      byte[] buf = new byte[4096];
      for (int i = 0; i < 1000; i++) {
        if (in.read(buf) < 0) {
          return true;
        }
      }
      return false;
    } catch (IOException e) {
      return !(e instanceof java.net.SocketTimeoutException);
    }
  }

  /** Sends one request and reads one whole reply. */
  private static boolean served(Socket s) throws IOException {
    s.getOutputStream().write(ActsProtocol.REQUEST_PACKET);
    byte[] head = s.getInputStream().readNBytes(1);
    return head.length == 1;
  }

  @Test
  void idleSocketsNeverKeepAFullServerFull() throws Exception {
    try (ActsServer srv = start(ServerSettings.DEFAULT.withMaxClients(4))) {
      List<Socket> squatters = new ArrayList<>();
      try {
        for (int i = 0; i < 16; i++) {
          squatters.add(connect(srv)); // the default --max-clients worth of silent sockets
        }
        try (Socket real = connect(srv)) {
          assertTrue(served(real), "a real client gets in past 16 silent sockets");
          assertTrue(served(real), "and stays");
        }
        assertTrue(closedByServer(squatters.get(0)), "the oldest silent socket made room");
        assertTrue(srv.clientsReplaced() >= 13, "replaced: " + srv.clientsReplaced());
        assertEquals(0, srv.clientsRefused());
      } finally {
        for (Socket s : squatters) {
          s.close();
        }
      }
    }
  }

  @Test
  void busyClientsAreNotReplaced() throws Exception {
    try (ActsServer srv = start(ServerSettings.DEFAULT.withMaxClients(2));
        Socket a = connect(srv);
        Socket b = connect(srv)) {
      assertTrue(served(a));
      assertTrue(served(b));
      try (Socket extra = connect(srv)) {
        assertTrue(closedByServer(extra), "a server full of busy clients refuses");
      }
      assertEquals(1, srv.clientsRefused());
      assertEquals(0, srv.clientsReplaced());
      assertTrue(served(a));
      assertTrue(served(b));
    }
  }

  @Test
  void aClientSilentPastTheIdleTimeoutIsDisconnected() throws Exception {
    try (ActsServer srv = start(ServerSettings.DEFAULT.withIdleTimeoutMillis(200));
        Socket silent = connect(srv);
        Socket spokeOnce = connect(srv)) {
      assertTrue(served(spokeOnce));
      assertTrue(closedByServer(silent), "silent client dropped");
      assertTrue(closedByServer(spokeOnce), "a client that stops asking is dropped too");
      assertEquals(2, srv.clientsDroppedIdle());
      assertEquals(0, srv.activeClients());
      assertFalse(srv.clientsRefused() > 0);
    }
  }

  /**
   * Waits (bounded, for an event, not a time) until the server has read {@code n} garbage bytes.
   */
  private static void awaitGarbage(ActsServer srv, long n) {
    for (long i = 0; i < 2_000_000_000L && srv.garbageBytes() < n; i++) {
      Thread.onSpinWait();
    }
    assertEquals(n, srv.garbageBytes());
  }

  @Test
  void aClientSendingOnlyGarbageIsIdleAndDroppedAfterTheIdleTimeout() throws Exception {
    VirtualClock clock = new VirtualClock();
    try (ActsServer srv = start(ServerSettings.DEFAULT, clock);
        Socket trickle = connect(srv);
        Socket real = connect(srv)) {
      for (int s = 0; s < 36; s += 6) {
        trickle.getOutputStream().write('x'); // one garbage byte
        awaitGarbage(srv, s / 6 + 1);
        assertTrue(served(real), "the real client asks and is answered");
        clock.advance(Duration.ofSeconds(6));
      }
      assertTrue(closedByServer(trickle), "36 s of garbage is 36 s idle: dropped");
      assertEquals(1, srv.clientsDroppedIdle());
      assertTrue(served(real), "the client that asks stays");
    }
  }

  @Test
  void aFullServerOfGarbageSendersMakesRoomForARealClient() throws Exception {
    VirtualClock clock = new VirtualClock();
    List<Socket> tricklers = new ArrayList<>();
    try (ActsServer srv = start(ServerSettings.DEFAULT.withMaxClients(4), clock)) {
      try {
        for (int i = 0; i < 4; i++) {
          tricklers.add(connect(srv));
        }
        for (int round = 1; round <= 3; round++) {
          for (Socket t : tricklers) {
            t.getOutputStream().write(0x55);
          }
          awaitGarbage(srv, 4L * round);
        }
        for (int i = 0; i < 30; i++) {
          try (Socket real = connect(srv)) {
            assertTrue(served(real), "real client " + i + " served past the garbage senders");
          }
          // the next one comes once this one is gone (an event, bounded)
          for (long k = 0; k < 2_000_000_000L && srv.activeClients() > 3; k++) {
            Thread.onSpinWait();
          }
        }
        assertEquals(0, srv.clientsRefused());
        assertEquals(1, srv.clientsReplaced(), "one garbage sender made room");
      } finally {
        for (Socket s : tricklers) {
          s.close();
        }
      }
    }
  }
}
