package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.clock.Clock;
import org.jaria.connection.ArTcpConnection;
import org.jaria.protocol.Hex;
import org.jaria.robot.ArRobot;
import org.jaria.sim.ServerCounters;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimServerOptions;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Execution;
import org.junit.jupiter.api.parallel.ExecutionMode;

/**
 * Hostile clients on a robot's TCP port (loopback only, a bounded number of sockets): squatters
 * that never finish the handshake, drips of one byte a second, open clients that go silent, floods
 * of connections to a taken robot, and a client that reconnects right after disconnecting. The
 * world runs on its own thread ten times faster than real time (the ARIA client in real time), so
 * the kernel's delivery of loopback bytes never races the simulated clock; the tests wait for what
 * the world thread does (a step listener), never for a time.
 *
 * <p>Each test has a world and sockets of its own and waits mostly on the world's real-time clock,
 * so the tests run side by side (see junit-platform.properties).
 */
@Execution(ExecutionMode.CONCURRENT)
class HostileSimClientsTest {

  private static final byte[] SYNC0 = Hex.parse("FA FB 03 00 00 00");
  private static final byte[] SYNC1 = Hex.parse("FA FB 03 01 00 01");
  private static final byte[] SYNC2 = Hex.parse("FA FB 03 02 00 02");

  private static SimWorld listeningWorld(double speedup) throws IOException {
    SimWorld w =
        SimWorld.bundled(
            "office",
            SimOptions.builder()
                .basePort(0)
                // The handshake limit is real time (HandshakeTime): 5 s of simulated time here.
                .server(SimServerOptions.DEFAULTS.withTimeouts((int) (5000 / speedup), 10_000))
                .build());
    w.addRobot("p3dx-sh");
    w.listen();
    w.startRealTime(speedup);
    return w;
  }

  private static SimWorld listeningWorld() throws IOException {
    return listeningWorld(10);
  }

  private static Socket connect(int port) throws IOException {
    Socket s = new Socket();
    s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 5000);
    s.setTcpNoDelay(true);
    s.setSoTimeout(5000);
    return s;
  }

  /**
   * Waits until {@code cond} holds after a step, at most {@code maxMillis} of simulated time (and
   * 30 s of real time); returns whether it did.
   */
  private static boolean stepUntil(SimWorld w, BooleanSupplier cond, long maxMillis)
      throws InterruptedException {
    long end = w.getClock().nanoTime() + maxMillis * 1_000_000;
    CountDownLatch latch = new CountDownLatch(1);
    Runnable check =
        () -> {
          if (cond.getAsBoolean() || w.getClock().nanoTime() >= end) {
            latch.countDown();
          }
        };
    w.addStepListener(check);
    try {
      latch.await(30, TimeUnit.SECONDS);
    } finally {
      w.removeStepListener(check);
    }
    return cond.getAsBoolean();
  }

  /** Waits until {@code millis} of simulated time have passed. */
  private static void passMillis(SimWorld w, long millis) throws InterruptedException {
    long end = w.getClock().nanoTime() + millis * 1_000_000;
    assertTrue(stepUntil(w, () -> w.getClock().nanoTime() >= end, millis + 1000));
  }

  /** Reads (bounded) until the server closes the socket; true if it did. */
  private static boolean closedByServer(Socket s) throws IOException {
    InputStream in = s.getInputStream();
    byte[] buf = new byte[4096];
    for (int i = 0; i < 10_000; i++) {
      try {
        if (in.read(buf) < 0) {
          return true;
        }
      } catch (java.net.SocketException reset) {
        return true;
      }
    }
    return false;
  }

  private static byte[] readFrame(Socket s) throws IOException {
    InputStream in = s.getInputStream();
    int b;
    while ((b = in.read()) != 0xFA) {
      if (b < 0) {
        throw new IOException("closed");
      }
    }
    in.read();
    int n = in.read();
    byte[] f = new byte[n + 3];
    f[0] = (byte) 0xFA;
    f[1] = (byte) 0xFB;
    f[2] = (byte) n;
    new java.io.DataInputStream(in).readFully(f, 3, n);
    return f;
  }

  /** SYNC0..2 with their echoes, then OPEN; returns once the robot is open. */
  private static void openByHand(SimWorld w, Socket s) throws Exception {
    for (byte[] sync : new byte[][] {SYNC0, SYNC1, SYNC2}) {
      s.getOutputStream().write(sync);
      assertEquals(sync[3], readFrame(s)[3], "echo");
    }
    s.getOutputStream().write(Hex.parse("FA FB 06 01 3B 01 00 02 3B"));
    assertTrue(stepUntil(w, () -> w.getRobot(0).isSessionOpen(), 2000), "opened");
  }

  @Test
  void aClientThatSendsNothingNeverKeepsTheNextOneOut() throws Exception {
    try (SimWorld w = listeningWorld();
        Socket squatter = connect(w.getRobot(0).getPort())) {
      assertTrue(stepUntil(w, () -> w.getRobot(0).isClientConnected(), 1000));
      try (Socket next = connect(w.getRobot(0).getPort())) {
        openByHand(w, next);
        assertTrue(
            stepUntil(w, () -> w.getServerCounters().timedOut() == 1, 6000),
            "squatter dropped after the handshake time");
        assertTrue(closedByServer(squatter));
        assertTrue(w.getRobot(0).isSessionOpen(), "the real client kept the robot");
        ServerCounters c = w.getServerCounters();
        assertEquals(2, c.sessions(), c.toString());
        assertEquals(0, c.refused(), c.toString());
      }
    }
  }

  @Test
  void aOneByteASecondDripIsDroppedToo() throws Exception {
    try (SimWorld w = listeningWorld();
        Socket drip = connect(w.getRobot(0).getPort())) {
      byte[] all = Hex.parse("FA FB 03 00 00 00 FA FB 03 01 00 01 FA FB 03 02 00 02");
      int sent = 0;
      while (w.getServerCounters().timedOut() == 0 && sent < all.length) {
        drip.getOutputStream().write(all[sent++]);
        passMillis(w, 1000);
      }
      assertEquals(1, w.getServerCounters().timedOut(), "dropped after " + sent + " bytes");
      assertTrue(sent <= 7, "within about 5 s: " + sent + " bytes sent");
      assertTrue(stepUntil(w, () -> w.connectedClientCount() == 0, 1000));
      assertTrue(closedByServer(drip));
    }
  }

  @Test
  void anOpenClientThatGoesSilentIsStoppedThenDropped() throws Exception {
    try (SimWorld w = listeningWorld();
        Socket c = connect(w.getRobot(0).getPort())) {
      SimRobot r = w.getRobot(0);
      openByHand(w, c);
      passMillis(w, 2500);
      assertTrue(r.isSessionOpen(), "the watchdog stops the robot first, keeping the client");
      assertTrue(stepUntil(w, () -> !r.isSessionOpen(), 8000), "silent client dropped");
      assertEquals(1, w.getServerCounters().timedOut());
      assertTrue(closedByServer(c));
    }
  }

  @Test
  void aFloodOfConnectionsToATakenRobotNeverTakesIt() throws Exception {
    // twice real time: the owner stays well within its 10 s of silence while the test reads
    try (SimWorld w = listeningWorld(2);
        Socket owner = connect(w.getRobot(0).getPort())) {
      int port = w.getRobot(0).getPort();
      openByHand(w, owner);
      List<Socket> flood = new ArrayList<>();
      try {
        for (int i = 0; i < 21; i++) {
          flood.add(connect(port));
          owner.getOutputStream().write(Hex.parse("FA FB 03 00 00 00")); // PULSE: still here
        }
        // they wait beside the robot, then go when their handshake time is up
        assertTrue(stepUntil(w, () -> w.getServerCounters().timedOut() == 21, 6000));
        for (Socket s : flood) {
          assertTrue(closedByServer(s));
        }
        assertTrue(w.getRobot(0).isSessionOpen(), "the owner keeps the robot");
        assertEquals(22, w.getServerCounters().sessions());
        assertEquals(0, w.getServerCounters().replaced());
      } finally {
        for (Socket s : flood) {
          s.close();
        }
      }
    }
  }

  @Test
  void anAriaClientCanReconnectRightAfterDisconnecting() throws Exception {
    try (SimWorld w = listeningWorld(1)) {
      int port = w.getRobot(0).getPort();
      for (int round = 0; round < 5; round++) {
        ArRobot first = new ArRobot("first-" + round);
        first.setParamsDirectory(null);
        first.setDeviceConnection(new ArTcpConnection("127.0.0.1", port, Clock.system()));
        assertTrue(first.blockingConnect(), "round " + round + ": " + first.getConnectFailure());
        first.disconnect();
        ArRobot second = new ArRobot("second-" + round);
        second.setParamsDirectory(null);
        second.setDeviceConnection(new ArTcpConnection("127.0.0.1", port, Clock.system()));
        assertTrue(second.blockingConnect(), "round " + round + ": " + second.getConnectFailure());
        second.disconnect();
      }
      assertEquals(0, w.getServerCounters().refused());
      assertFalse(w.getServerCounters().sessions() < 10);
    }
  }
}
