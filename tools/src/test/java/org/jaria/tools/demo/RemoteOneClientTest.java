package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * A {@code --remote} demo makes exactly one connection, which is all MobileSim and AMRISim allow:
 * their robot's port takes one client and closes while it lasts (and AMRISim may move the robot to
 * the next port when it ends). The demo used to try the port with a connection of its own first, so
 * against AMRISim its real connection found nobody. Here a port that, like MobileSim's, accepts one
 * client and then closes stands in front of a real JAria simulator.
 */
@Tag("slow")
class RemoteOneClientTest {

  /** Accepts one client, closes its port (as MobileSim does), relays to {@code target}. */
  private static final class OneClientPort implements AutoCloseable {
    final ServerSocket server;
    final AtomicInteger accepted = new AtomicInteger();
    private final Thread acceptor;
    private volatile Socket client;
    private volatile Socket upstream;
    private volatile Thread back;

    OneClientPort(int target) throws IOException {
      server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
      acceptor =
          new Thread(
              () -> {
                try {
                  client = server.accept();
                  accepted.incrementAndGet();
                  server.close(); // MobileSim listens again only when its client is gone
                  upstream = new Socket(InetAddress.getLoopbackAddress(), target);
                  back = new Thread(() -> copy(upstream, client), "one-client-port-to-client");
                  back.start();
                  copy(client, upstream);
                } catch (IOException closed) {
                  // the test is over
                }
              },
              "one-client-port");
      acceptor.start();
    }

    int port() {
      return server.getLocalPort();
    }

    private static void copy(Socket from, Socket to) {
      byte[] buf = new byte[4096];
      try (from;
          to) {
        InputStream in = from.getInputStream();
        OutputStream out = to.getOutputStream();
        int n;
        while ((n = in.read(buf)) >= 0) {
          out.write(buf, 0, n);
        }
      } catch (IOException ended) {
        // either side left: both sockets close
      }
    }

    @Override
    public void close() throws IOException {
      server.close();
      for (Socket s : new Socket[] {client, upstream}) {
        if (s != null) {
          s.close();
        }
      }
      join(acceptor);
      join(back);
    }

    private static void join(Thread t) {
      if (t == null) {
        return;
      }
      try {
        t.join();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }

  @Test
  void gotoRemoteReachesItsGoalThroughAPortThatTakesOneClient() throws Exception {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().basePort(0).build())) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world.listen();
      world.startRealTime(1);
      try (OneClientPort port = new OneClientPort(robot.getPort())) {
        CommandLine cli = JariaCli.commandLine();
        StringWriter out = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(out, true));
        int status =
            cli.execute("demo", "goto", "--remote", "127.0.0.1:" + port.port(), "--pose", "500,0");
        assertEquals(0, status, out.toString());
        assertTrue(out.toString().contains("all goals reached"), out.toString());
        assertEquals(1, port.accepted.get(), "one connection, the program's own");
      }
    }
  }

  @Test
  void anUnknownHostIsSaidWithTheUsersOption() {
    CommandLine cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(out, true));
    int status = cli.execute("demo", "goto", "--remote", "no-such-host.invalid:8101");
    assertEquals(1, status, out.toString());
    assertTrue(
        out.toString().contains("unknown host 'no-such-host.invalid' in --remote"), out.toString());
  }
}
