package org.jaria.tools.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ArACTS_1_2;
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
 * The squatting rows of {@code jaria bench hostile}: silent connections that connect again whenever
 * they are dropped (2, 10 and 50 on a robot's port) and connections that trickle one garbage byte a
 * second (16, on the robot's port and on the ACTS port, the ACTS server's whole client limit). For
 * each, how many real clients out of 30 were served while the attack went on, and the p99 of the
 * interval between a served ARIA program's robot cycles (one per SIP: 100 ms when all is well);
 * then how long 1,000 connects to a robot's port take. Simulator and ACTS server run in this
 * process in real time with their default settings; the attackers are {@link Attackers}.
 */
final class SquatterBenchmark {

  private SquatterBenchmark() {}

  /** Appends the rows (fewer and shorter attempts when {@code quick}). */
  static void rows(StringBuilder out, boolean quick) throws Exception {
    int attempts = quick ? 5 : 30;
    long runMillis = quick ? 500 : 1000;
    out.append(
        String.format(
            Locale.ROOT,
            "%n%-40s %12s %13s %8s %8s %8s%n",
            "attack (real clients during it)",
            "served",
            "cycle p99 ms",
            "dropped",
            "refused",
            "replaced"));
    for (int n : new int[] {2, 10, 50}) {
      simRow(out, n + " squatters reconnecting", n, false, attempts, runMillis);
    }
    simRow(out, "16 trickling a garbage byte/s", 16, true, attempts, runMillis);
    actsRow(out, attempts, runMillis);
    connectBurst(out, quick ? 200 : 1000);
  }

  private static SimWorld world(int robots) throws IOException {
    SimWorld w = SimWorld.bundled("office", SimOptions.builder().basePort(0).build());
    for (int i = 0; i < robots; i++) {
      w.addRobot("p3dx-sh");
    }
    w.listen();
    w.startRealTime(1);
    return w;
  }

  /** Real ARIA programs connect to a robot whose port {@code n} attackers keep at. */
  private static void simRow(
      StringBuilder out, String what, int n, boolean trickle, int attempts, long runMillis)
      throws Exception {
    try (SimWorld w = world(1)) {
      int port = w.getRobot(0).getPort();
      CycleIntervals cycles = new CycleIntervals();
      int served = 0;
      try (Attackers a = new Attackers(port, n, trickle)) {
        a.awaitConnected();
        for (int i = 0; i < attempts; i++) {
          ArRobot r = program("real-" + i, port);
          if (r.blockingConnect()) {
            served++;
            cycles.attach(r);
            r.runAsync(true);
            Thread.sleep(runMillis); // the program runs a while; nothing waits on a time here
            stop(r);
          }
        }
      }
      ServerCounters c = w.getServerCounters();
      row(out, "sim: " + what, served, attempts, cycles, c.timedOut(), c.refused(), c.replaced());
    }
  }

  /** ACTS clients, and a robot program using ACTS every cycle, while 16 trickle garbage. */
  private static void actsRow(StringBuilder out, int attempts, long runMillis) throws Exception {
    ActsServer acts =
        new ActsServer(
            new VisionPipeline(
                new StillImageSource(TestScene.render(160, 120)),
                new ChannelBank(),
                TrackerSettings.DEFAULT),
            ServerSettings.DEFAULT.withAddress("127.0.0.1", 0),
            Clock.system());
    try (acts;
        SimWorld w = world(1)) {
      acts.start();
      acts.awaitFrames(1, 10, TimeUnit.SECONDS);
      CycleIntervals cycles = new CycleIntervals();
      int served = 0;
      try (Attackers a = new Attackers(acts.getPort(), 16, true)) {
        a.awaitConnected();
        ArRobot robot = program("acts-user", w.getRobot(0).getPort());
        try (ArACTS_1_2 inCycle = new ArACTS_1_2()) {
          boolean running =
              robot.blockingConnect() && inCycle.openPort(robot, "127.0.0.1", acts.getPort());
          if (running) {
            cycles.attach(robot);
            robot.runAsync(true);
          }
          for (int i = 0; i < attempts; i++) {
            if (actsServes(acts.getPort())) {
              served++;
            }
            Thread.sleep(runMillis / 10); // spread the attempts over the attack
          }
          if (running) {
            Thread.sleep(runMillis); // and the program runs on a while, as in the other rows
          }
          stop(robot);
        }
      }
      row(
          out,
          "acts: 16 trickling a garbage byte/s",
          served,
          attempts,
          cycles,
          acts.clientsDroppedIdle(),
          acts.clientsRefused(),
          acts.clientsReplaced());
    }
  }

  private static boolean actsServes(int port) {
    try (ArACTS_1_2 c = new ArACTS_1_2()) {
      c.setReadTimeouts(2000, 2000);
      return c.openPort("127.0.0.1", port) && c.requestPacket() && c.receiveBlobInfo();
    }
  }

  /** How long {@code n} connects (each closed at once) to a robot's port take. */
  private static void connectBurst(StringBuilder out, int n) throws Exception {
    try (SimWorld w = world(1)) {
      int port = w.getRobot(0).getPort();
      long slowest = 0;
      long t0 = System.nanoTime();
      for (int i = 0; i < n; i++) {
        long t = System.nanoTime();
        try (Socket s = new Socket()) {
          s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 10_000);
        }
        slowest = Math.max(slowest, System.nanoTime() - t);
      }
      out.append(
          String.format(
              Locale.ROOT,
              "sim: %,d connects to a robot's port in %.2f s, the slowest %.1f ms%n",
              n,
              (System.nanoTime() - t0) / 1e9,
              slowest / 1e6));
    }
  }

  /** Stops a program's cycle thread and disconnects it. */
  private static void stop(ArRobot r) throws InterruptedException {
    r.stopRunning();
    r.waitForRunExit();
    r.disconnect();
  }

  private static ArRobot program(String name, int port) {
    ArRobot r = new ArRobot(name);
    r.setParamsDirectory(null);
    r.setDeviceConnection(new ArTcpConnection("127.0.0.1", port, Clock.system()));
    return r;
  }

  private static void row(
      StringBuilder out,
      String what,
      int served,
      int attempts,
      CycleIntervals cycles,
      long dropped,
      long refused,
      long replaced) {
    out.append(
        String.format(
            Locale.ROOT,
            "%-40s %12s %13s %8d %8d %8d%n",
            what,
            served + " of " + attempts,
            cycles.count() == 0 ? "-" : String.format(Locale.ROOT, "%.1f", cycles.p99Millis()),
            dropped,
            refused,
            replaced));
  }

  /** The intervals between a robot's cycles, gathered over several runs. */
  private static final class CycleIntervals {
    private long[] nanos = new long[256];
    private int n;
    private long last;

    /** Records each interval between {@code r}'s cycles from now on (a new robot each time). */
    synchronized void attach(ArRobot r) {
      last = 0;
      r.addUserTask("bench-cycle", 1, this::cycle);
    }

    private synchronized void cycle() {
      long now = System.nanoTime();
      if (last != 0) {
        if (n == nanos.length) {
          nanos = Arrays.copyOf(nanos, n * 2);
        }
        nanos[n++] = now - last;
      }
      last = now;
    }

    synchronized int count() {
      return n;
    }

    synchronized double p99Millis() {
      long[] s = Arrays.copyOf(nanos, n);
      Arrays.sort(s);
      return s[Math.max(0, (int) Math.ceil(0.99 * n) - 1)] / 1e6;
    }
  }
}
