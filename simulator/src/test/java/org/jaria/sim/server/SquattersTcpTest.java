package org.jaria.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import org.jaria.connection.ArTcpConnection;
import org.jaria.robot.ArRobot;
import org.jaria.sim.ServerCounters;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/**
 * Squatters on a robot's real TCP port, with the world stepped by hand and an ARIA client driven in
 * lockstep on the world's virtual clock: time moves only when the test steps, so the handshake and
 * replace times are exact. (The kernel delivers loopback bytes within the send; the loops below
 * only wait for that, bounded by a number of steps, never by time.)
 */
class SquattersTcpTest {

  /** Silent connections that connect again whenever the robot drops them. */
  private static final class Squatters implements AutoCloseable {
    private final int port;
    private final SocketChannel[] socks;
    private final ByteBuffer buf = ByteBuffer.allocate(4096);
    long reconnects;

    Squatters(int port, int n) throws IOException {
      this.port = port;
      socks = new SocketChannel[n];
      for (int i = 0; i < n; i++) {
        socks[i] = open();
      }
    }

    private SocketChannel open() throws IOException {
      SocketChannel c =
          SocketChannel.open(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
      c.configureBlocking(false);
      return c;
    }

    /** Connects again every squatter the robot closed. */
    void keepAt() throws IOException {
      for (int i = 0; i < socks.length; i++) {
        int n;
        try {
          buf.clear();
          n = socks[i].read(buf);
        } catch (IOException reset) {
          n = -1;
        }
        if (n < 0) {
          socks[i].close();
          socks[i] = open();
          reconnects++;
        }
      }
    }

    @Override
    public void close() throws IOException {
      for (SocketChannel c : socks) {
        c.close();
      }
    }
  }

  private static SimWorld world() throws IOException {
    SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build());
    w.addRobot("p3dx-sh");
    w.listen();
    return w;
  }

  /** Connects an ARIA client in lockstep while the squatters keep at it; returns whether it did. */
  private static boolean connectPast(SimWorld w, Squatters sq, ArRobot robot) throws IOException {
    robot.asyncConnect();
    for (int i = 0; i < 3000 && robot.isConnecting(); i++) {
      w.step();
      robot.loopOnce();
      sq.keepAt();
    }
    return robot.isConnected();
  }

  @Test
  void squattersThatReconnectWheneverDroppedNeverKeepAnAriaClientOut() throws Exception {
    try (SimWorld w = world();
        Squatters sq = new Squatters(w.getRobot(0).getPort(), 10)) {
      int port = w.getRobot(0).getPort();
      for (int round = 0; round < 5; round++) {
        ArRobot robot = new ArRobot("real-" + round, w.getClock(), true);
        robot.setParamsDirectory(null);
        robot.setDeviceConnection(new ArTcpConnection("127.0.0.1", port, w.getClock()));
        assertTrue(connectPast(w, sq, robot), "round " + round + ": " + robot.getConnectFailure());
        // 3 s of squatters coming and going while the program runs
        for (int i = 0; i < 300; i++) {
          w.step();
          robot.loopOnce();
          sq.keepAt();
        }
        assertTrue(robot.isConnected(), "round " + round + ": the program keeps its robot");
        assertTrue(w.getRobot(0).isSessionOpen());
        robot.disconnect();
      }
      ServerCounters c = w.getServerCounters();
      assertTrue(sq.reconnects >= 10, "the squatters were dropped and came back: " + c);
      assertEquals(0, c.replaced(), c.toString());
    }
  }

  @Test
  void aBurstOfConnectsWaitsInTheQueueWhileTheWorldIsBusy() throws Exception {
    // the world does not step here, so nothing accepts: every connect must fit in the queue
    try (SimWorld w = world()) {
      List<Socket> burst = new ArrayList<>();
      try {
        for (int i = 0; i < 100; i++) {
          Socket s = new Socket();
          burst.add(s);
          s.connect(
              new InetSocketAddress(InetAddress.getLoopbackAddress(), w.getRobot(0).getPort()),
              3000);
        }
        for (int i = 0; i < 100 && w.getServerCounters().sessions() < 100; i++) {
          w.step();
        }
        ServerCounters c = w.getServerCounters();
        assertEquals(100, c.sessions(), c.toString());
        assertEquals(100 - RobotClients.MAX_CANDIDATES, c.refused(), "the stalest made room");
      } finally {
        for (Socket s : burst) {
          s.close();
        }
      }
    }
  }
}
