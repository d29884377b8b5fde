package org.jaria.tools.bench;

import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.image.StillImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.acts.server.ActsServer;
import org.jaria.acts.server.ServerSettings;
import org.jaria.acts.server.VisionPipeline;
import org.jaria.clock.Clock;
import org.jaria.connection.ArTcpConnection;
import org.jaria.robot.ArRobot;
import org.jaria.sim.ServerCounters;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;

/**
 * {@code jaria bench hostile}: what hostile clients on the loopback do to the simulator's robot
 * port and the ACTS server: a flood of connections that never send a byte, then one real client (is
 * it served?), with the connections refused and dropped and this process's memory (RSS) and thread
 * count before, during and after; and ARIA clients that reconnect right after disconnecting. Both
 * servers run in this process with their default settings.
 */
public final class HostileBenchmark {

  private static final byte[] SYNC0 = {(byte) 0xFA, (byte) 0xFB, 3, 0, 0, 0};

  private HostileBenchmark() {}

  /** Runs the benchmark and returns its table. */
  public static String run(boolean quick) throws Exception {
    StringBuilder out = new StringBuilder(floodsAndReconnects(quick));
    SquatterBenchmark.rows(out, quick);
    out.append(GuiServerHostileBenchmark.run(quick));
    return out.toString();
  }

  /**
   * The table's header and its own rows: the floods of silent connections and the reconnects. The
   * squatting and guiServer rows have their own tests, so the test of these rows does not run them
   * a second time.
   */
  static String floodsAndReconnects(boolean quick) throws Exception {
    int flood = quick ? 50 : 200;
    StringBuilder out = new StringBuilder();
    out.append(
        String.format(
            Locale.ROOT,
            "%-34s %8s %8s %8s %8s %7s %22s %16s%n",
            "scenario",
            "sockets",
            "refused",
            "dropped",
            "replaced",
            "served",
            "RSS MiB before/flood/after",
            "threads b/f/a"));
    simFlood(out, flood);
    actsFlood(out, flood);
    reconnects(out, quick ? 5 : 25);
    return out.toString();
  }

  /** The simulator (10x real time, so its 5 s handshake timeout passes in 0.5 s). */
  private static void simFlood(StringBuilder out, int n) throws Exception {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build())) {
      w.addRobot("p3dx-sh");
      w.listen();
      w.startRealTime(10);
      int port = w.getRobot(0).getPort();
      Figures before = Figures.now();
      List<Socket> sockets = new ArrayList<>();
      Figures during;
      boolean served;
      try {
        for (int i = 0; i < n; i++) {
          sockets.add(connect(port));
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (accounted(w.getServerCounters()) < n && System.nanoTime() < deadline) {
          awaitTicks(w, 10);
        }
        during = Figures.now();
        try (Socket real = connect(port)) {
          real.getOutputStream().write(SYNC0);
          served = readsFrame(real.getInputStream());
        }
      } finally {
        for (Socket s : sockets) {
          s.close();
        }
      }
      ServerCounters c = w.getServerCounters();
      row(
          out,
          "sim: " + n + " silent connections",
          n,
          c.refused(),
          c.timedOut(),
          0,
          served,
          before,
          during,
          Figures.now());
    }
  }

  private static long accounted(ServerCounters c) {
    return c.refused() + c.timedOut();
  }

  /** Waits until the world has stepped {@code ticks} more times (its own listener says so). */
  private static void awaitTicks(SimWorld w, int ticks) throws InterruptedException {
    java.util.concurrent.CountDownLatch latch = new java.util.concurrent.CountDownLatch(ticks);
    Runnable r = latch::countDown;
    w.addStepListener(r);
    try {
      latch.await(5, TimeUnit.SECONDS);
    } finally {
      w.removeStepListener(r);
    }
  }

  /** The ACTS server with its defaults (16 clients, 30 s idle timeout). */
  private static void actsFlood(StringBuilder out, int n) throws Exception {
    ActsServer srv =
        new ActsServer(
            new VisionPipeline(
                new StillImageSource(TestScene.render(160, 120)),
                new ChannelBank(),
                TrackerSettings.DEFAULT),
            ServerSettings.DEFAULT.withAddress("127.0.0.1", 0),
            Clock.system());
    try (srv) {
      srv.start();
      srv.awaitFrames(1, 10, TimeUnit.SECONDS);
      Figures before = Figures.now();
      List<Socket> sockets = new ArrayList<>();
      Figures during;
      boolean served;
      try {
        for (int i = 0; i < n; i++) {
          sockets.add(connect(srv.getPort()));
        }
        try (Socket real = connect(srv.getPort())) {
          real.getOutputStream().write(ActsProtocol.REQUEST_PACKET);
          served = real.getInputStream().read() >= 0;
        }
        during = Figures.now();
      } finally {
        for (Socket s : sockets) {
          s.close();
        }
      }
      row(
          out,
          "acts: " + n + " silent connections",
          n,
          srv.clientsRefused(),
          srv.clientsDroppedIdle(),
          srv.clientsReplaced(),
          served,
          before,
          during,
          Figures.now());
    }
  }

  /** ARIA clients that disconnect and at once connect again, on a real-time simulator. */
  private static void reconnects(StringBuilder out, int rounds) throws Exception {
    try (SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build())) {
      w.addRobot("p3dx-sh");
      w.listen();
      w.startRealTime(1);
      int port = w.getRobot(0).getPort();
      Figures before = Figures.now();
      int ok = 0;
      for (int i = 0; i < rounds; i++) {
        ArRobot a = robot("first", port);
        if (!a.blockingConnect()) {
          continue;
        }
        a.disconnect();
        ArRobot b = robot("second", port);
        if (b.blockingConnect()) {
          ok++;
          b.disconnect();
        }
      }
      ServerCounters c = w.getServerCounters();
      out.append(
          String.format(
              Locale.ROOT,
              "sim: disconnect + reconnect        %d of %d reconnects accepted (%d refused)%n",
              ok,
              rounds,
              c.refused()));
      Figures after = Figures.now();
      out.append(
          String.format(
              Locale.ROOT,
              "%-34s RSS %d -> %d MiB, threads %d -> %d%n",
              "",
              before.rssMib,
              after.rssMib,
              before.threads,
              after.threads));
    }
  }

  private static ArRobot robot(String name, int port) {
    ArRobot r = new ArRobot(name);
    r.setParamsDirectory(null);
    r.setDeviceConnection(new ArTcpConnection("127.0.0.1", port, Clock.system()));
    return r;
  }

  private static Socket connect(int port) throws IOException {
    Socket s = new Socket();
    s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 5000);
    s.setSoTimeout(10_000);
    return s;
  }

  private static boolean readsFrame(InputStream in) {
    try {
      return in.read() == 0xFA;
    } catch (IOException e) {
      return false;
    }
  }

  private static void row(
      StringBuilder out,
      String what,
      int sockets,
      long refused,
      long dropped,
      long replaced,
      boolean served,
      Figures before,
      Figures during,
      Figures after) {
    out.append(
        String.format(
            Locale.ROOT,
            "%-34s %8d %8d %8d %8d %7s %22s %16s%n",
            what,
            sockets,
            refused,
            dropped,
            replaced,
            served ? "yes" : "NO",
            before.rssMib + " / " + during.rssMib + " / " + after.rssMib,
            before.threads + " / " + during.threads + " / " + after.threads));
  }

  /** This process's resident memory (Linux; -1 elsewhere) and live threads. */
  private record Figures(long rssMib, int threads) {
    static Figures now() {
      long rss = -1;
      try {
        for (String l :
            Files.readAllLines(Path.of("/proc/self/status"), StandardCharsets.ISO_8859_1)) {
          if (l.startsWith("VmRSS:")) {
            rss = Long.parseLong(l.replaceAll("[^0-9]", "")) / 1024;
          }
        }
      } catch (IOException | NumberFormatException e) {
        rss = -1;
      }
      return new Figures(rss, ManagementFactory.getThreadMXBean().getThreadCount());
    }
  }
}
