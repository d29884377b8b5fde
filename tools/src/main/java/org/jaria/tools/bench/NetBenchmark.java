package org.jaria.tools.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.client.ArNetPacketArgs;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ArServerClient;
import org.jaria.net.server.ServerOptions;
import org.jaria.simguiserver.SimulatedGuiServer;

/**
 * The network server's reliability figures ({@code ./jaria bench net}): the robot's sync-cycle time
 * with no clients, then with 20 monitors subscribed at 10 Hz to what a monitor draws plus one
 * hostile client sending garbage, and the server's queue for a client that stops reading. The robot
 * is a simulated p3dx-sh wandering the office map in real time, with threaded SonARNL localization
 * and path planning, exactly as {@code jaria demo guiserver} runs it.
 */
public final class NetBenchmark {

  /** What a monitor subscribes to. */
  static final List<String> MONITOR_DATA =
      List.of("update", "getSensorCurrent", "getLocState", "getLocPoints", "getPath", "getStrings");

  /** Long enough for a stalled socket to fill and the stall timeout to pass. */
  private static final Duration SLOW_PHASE = Duration.ofSeconds(25);

  private NetBenchmark() {}

  /** Percentiles of cycle times, ms. */
  record CycleStats(int cycles, double p50, double p99, double max) {
    static CycleStats of(long[] nanos) {
      long[] s = nanos.clone();
      Arrays.sort(s);
      if (s.length == 0) {
        return new CycleStats(0, Double.NaN, Double.NaN, Double.NaN);
      }
      return new CycleStats(
          s.length, pct(s, 0.50) / 1e6, pct(s, 0.99) / 1e6, s[s.length - 1] / 1e6);
    }

    private static double pct(long[] sorted, double p) {
      int i = (int) Math.ceil(p * sorted.length) - 1;
      return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }
  }

  /** Records the duration of every robot cycle (the world's step listener runs after each). */
  private static final class CycleSampler {
    private final SimulatedGuiServer s;
    private long lastCounter;
    private long[] samples = new long[1024];
    private int n;
    private final Runnable listener = this::afterStep;

    CycleSampler(SimulatedGuiServer s) {
      this.s = s;
      lastCounter = s.robot().getCounter();
      s.world().addStepListener(listener);
    }

    private synchronized void afterStep() {
      long c = s.robot().getCounter();
      if (c != lastCounter) {
        lastCounter = c;
        if (n == samples.length) {
          samples = Arrays.copyOf(samples, n * 2);
        }
        samples[n++] = s.robot().getLastCycleNanos();
      }
    }

    synchronized void reset() {
      n = 0;
    }

    synchronized long[] take() {
      return Arrays.copyOf(samples, n);
    }

    void close() {
      s.world().removeStepListener(listener);
    }
  }

  /** A client that sends garbage and reconnects whenever the server drops it. */
  private static final class Hostile implements Runnable {
    private final int port;
    private final Random rnd = new Random(99);
    private volatile boolean stop;
    final AtomicLong connections = new AtomicLong();
    final AtomicLong droppedByServer = new AtomicLong();
    final AtomicLong bytesSent = new AtomicLong();
    private final Thread thread = new Thread(this, "bench-hostile-client");

    Hostile(int port) {
      this.port = port;
      thread.setDaemon(true);
      thread.start();
    }

    @Override
    public void run() {
      while (!stop) {
        try (Socket s = new Socket()) {
          s.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 2000);
          connections.incrementAndGet();
          s.setSoTimeout(1);
          OutputStream out = s.getOutputStream();
          InputStream in = s.getInputStream();
          byte[] chunk = new byte[512];
          boolean first = true;
          while (!stop) {
            rnd.nextBytes(chunk);
            if (first && rnd.nextBoolean()) {
              // ArNetworking's sync bytes and a plausible length, so the garbage reaches the
              // checksum.
              int len = 200 + rnd.nextInt(300);
              chunk[0] = 0x0f;
              chunk[1] = 0x0c;
              chunk[2] = (byte) len;
              chunk[3] = (byte) (len >> 8);
            }
            first = false;
            out.write(chunk);
            bytesSent.addAndGet(chunk.length);
            if (closed(in)) {
              droppedByServer.incrementAndGet();
              break;
            }
          }
        } catch (IOException e) {
          // Writing to a connection the server closed: that is a drop too.
          droppedByServer.incrementAndGet();
        }
        try {
          // Reconnect at once, but no more than a thousand times a second.
          TimeUnit.MILLISECONDS.sleep(1);
        } catch (InterruptedException e) {
          return;
        }
      }
    }

    private static boolean closed(InputStream in) throws IOException {
      try {
        byte[] b = new byte[4096];
        while (true) {
          int k = in.read(b);
          if (k < 0) {
            return true;
          }
        }
      } catch (SocketTimeoutException e) {
        return false;
      }
    }

    void stop() throws InterruptedException {
      stop = true;
      thread.join(5000);
    }
  }

  /**
   * Runs the benchmark.
   *
   * @param quick 10 s phases instead of 30 s
   * @return the report, Markdown tables
   */
  public static String run(boolean quick) throws Exception {
    Duration phase = Duration.ofSeconds(quick ? 10 : 30);
    int monitors = 20;
    long rateMs = 100;
    StringBuilder sb = new StringBuilder();
    sb.append("# JAria network server benchmark").append(quick ? " (quick)" : "").append("\n\n");
    sb.append(
        String.format(
            Locale.ROOT,
            "Java %s on %d cores. A simulated p3dx-sh wanders the office map in real time (robot"
                + " cycle 100 ms) with threaded SonARNL localization and path planning; the"
                + " guiServer, the clients and the robot share this computer. %d s per phase.%n%n",
            System.getProperty("java.version"),
            Runtime.getRuntime().availableProcessors(),
            phase.toSeconds()));
    sb.append(
        String.format(
            Locale.ROOT,
            "System load average when it started: %.1f (other programs share the cores).%n%n",
            ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage()));
    // A bounded kernel send buffer per client (as a robot with little memory would set), so a
    // client that stops reading fills it in seconds rather than minutes.
    ServerOptions so =
        ServerOptions.builder()
            .port(0)
            .bindAddress("127.0.0.1")
            .socketSendBuffer(64 * 1024)
            .build();
    ArMap map = ArMap.loadBundled("office");
    try (SimulatedGuiServer s =
        SimulatedGuiServer.start(
            new SimulatedGuiServer.Options(
                map, "office.map", "p3dx-sh", 1, so, ArnlNavigation.Mode.THREADED, 1.0, false))) {
      ArServerBase server = s.gui().getServer();
      if (!server.runOnCycle(() -> s.gui().getModeWander().activate())) {
        throw new IllegalStateException("the robot's command queue is full");
      }
      CycleSampler sampler = new CycleSampler(s);
      try {
        // Phase 1: nobody connected.
        pause(Duration.ofSeconds(2));
        sampler.reset();
        pause(phase);
        CycleStats alone = CycleStats.of(sampler.take());

        // Phase 2: 20 monitors at 10 Hz and a hostile client.
        List<ArClientBase> clients = new ArrayList<>();
        List<AtomicLong> robotUpdates = new ArrayList<>();
        AtomicLong totalUpdates = new AtomicLong();
        for (int i = 0; i < monitors; i++) {
          ArClientBase c = new ArClientBase("bench-monitor-" + (i + 1));
          AtomicLong u = new AtomicLong();
          robotUpdates.add(u);
          c.addHandler("update", p -> u.incrementAndGet());
          for (String d : MONITOR_DATA) {
            c.addHandler(d, p -> totalUpdates.incrementAndGet());
            // ArNetworking sends one named sensor's readings per request.
            var unused =
                d.equals("getSensorCurrent")
                    ? c.request(d, rateMs, ArNetPacketArgs.of("sonar"))
                    : c.request(d, rateMs);
          }
          c.connect("127.0.0.1", s.port(), "", "");
          clients.add(c);
        }
        Hostile hostile = new Hostile(s.port());
        pause(Duration.ofSeconds(2));
        long malformed0 = server.getStats().getMalformed();
        long updates0 = totalUpdates.get();
        long robot0 = robotUpdates.stream().mapToLong(AtomicLong::get).sum();
        long hostile0 = hostile.connections.get();
        long hostileDrops0 = hostile.droppedByServer.get();
        long full0 = server.getStats().getRefusedFull();
        sampler.reset();
        long t0 = System.nanoTime();
        pause(phase);
        long hostileConnections = hostile.connections.get() - hostile0;
        long hostileDrops = hostile.droppedByServer.get() - hostileDrops0;
        long malformed = server.getStats().getMalformed() - malformed0;
        long refusedFull = server.getStats().getRefusedFull() - full0;
        double secs = (System.nanoTime() - t0) / 1e9;
        CycleStats loaded = CycleStats.of(sampler.take());
        long updates = totalUpdates.get() - updates0;
        long robotRate = robotUpdates.stream().mapToLong(AtomicLong::get).sum() - robot0;
        hostile.stop();
        long stillConnected = clients.stream().filter(ArClientBase::isConnected).count();
        for (ArClientBase c : clients) {
          c.close();
        }

        sb.append("## Robot cycle time (budget: the 100 ms cycle)\n\n");
        sb.append("| phase | cycles | p50 ms | p99 ms | max ms |\n|---|---:|---:|---:|---:|\n");
        row(sb, "no clients", alone);
        row(sb, monitors + " monitors at 10 Hz + 1 hostile client", loaded);
        sb.append("\n## The clients during the loaded phase\n\n");
        sb.append("| figure | value |\n|---|---:|\n");
        sb.append(
            String.format(
                Locale.ROOT,
                "| monitors still connected at the end | %d of %d |%n",
                stillConnected,
                monitors));
        sb.append(
            String.format(
                Locale.ROOT,
                "| robot-state updates per monitor per second | %.1f |%n",
                robotRate / secs / monitors));
        sb.append(
            String.format(
                Locale.ROOT,
                "| updates of all %d data per second, all monitors | %.0f |%n",
                MONITOR_DATA.size(),
                updates / secs));
        sb.append(
            String.format(
                Locale.ROOT,
                "| hostile connections / seen dropped by the server | %d / %d (%.0f per second) |%n",
                hostileConnections,
                hostileDrops,
                hostileConnections / secs));
        sb.append(
            String.format(
                Locale.ROOT,
                "| server's count: closed for malformed frames / refused as full | %d / %d |%n",
                malformed,
                refusedFull));
        sb.append(
            String.format(
                Locale.ROOT,
                "| garbage sent by the hostile client | %d kB |%n",
                hostile.bytesSent.get() / 1000));

        // Phase 3: a client that subscribes to everything and never reads.
        sb.append("\n## A client that stops reading\n\n");
        sb.append(slowReader(s, phase.compareTo(SLOW_PHASE) < 0 ? SLOW_PHASE : phase, sampler));
      } finally {
        sampler.close();
      }
    }
    return sb.toString();
  }

  private static String slowReader(SimulatedGuiServer s, Duration phase, CycleSampler sampler)
      throws Exception {
    ArServerBase server = s.gui().getServer();
    ServerOptions o = server.getOptions();
    long heapBefore = usedHeap();
    // A client that stops reading (a small receive window, as a stuck program's socket fills)
    // and never sends again, so only the server's stall detection can tell.
    try (Socket raw = new Socket()) {
      raw.setReceiveBufferSize(4096);
      raw.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), s.port()), 2000);
      OutputStream out = raw.getOutputStream();
      // ArNetworking's login by hand (the server is open, so the digest is not checked).
      ArNetPacket intro = new ArNetPacket(Protocol.CLIENT_INTRODUCTION);
      intro.uByte2ToBuf(0).strToBuf("stuck").dataToBuf(new byte[16]).strToBuf("").byteToBuf(0);
      out.write(intro.toWire());
      out.write(new ArNetPacket(Protocol.CLIENT_TCP_ONLY).toWire());
      for (String d : List.of("update", "getSensorCurrent", "getLocPoints", "getMap", "getPath")) {
        int id =
            server.dataList().stream()
                .filter(x -> x.name().equals(d))
                .findFirst()
                .orElseThrow()
                .id();
        ArNetPacket r = new ArNetPacket(Protocol.CLIENT_REQUEST);
        r.uByte2ToBuf(id).byte4ToBuf(50);
        out.write(r.toWire());
      }
      out.flush();
      ArServerClient c = waitForClient(server);
      sampler.reset();
      long start = System.nanoTime();
      long end = start + phase.toNanos();
      long droppedAt = -1;
      while (System.nanoTime() < end) {
        if (c.isClosed() && droppedAt < 0) {
          droppedAt = System.nanoTime() - start;
        }
        pause(Duration.ofMillis(20));
      }
      CycleStats during = CycleStats.of(sampler.take());
      long heapAfter = usedHeap();
      StringBuilder sb = new StringBuilder();
      sb.append("| figure | value |\n|---|---:|\n");
      sb.append("| subscriptions (update, sensors, particles, map, path) at 20 Hz | 5 |\n");
      sb.append(
          String.format(
              Locale.ROOT,
              "| server socket send buffer (SO_SNDBUF) | %d kB |%n",
              o.socketSendBuffer() / 1024));
      sb.append(
          String.format(
              Locale.ROOT,
              "| bytes the socket took before stalling | %d kB |%n",
              c.getBytesSent() / 1000));
      sb.append(
          String.format(
              Locale.ROOT,
              "| peak bytes queued for it in the server | %d kB |%n",
              c.getPeakQueuedBytes() / 1000));
      sb.append(
          String.format(
              Locale.ROOT,
              "| updates replaced by newer ones while waiting | %d |%n",
              c.getCoalescedCount()));
      sb.append(
          String.format(
              Locale.ROOT,
              "| dropped after (stall timeout %d s) | %s |%n",
              o.stallTimeout().toSeconds(),
              droppedAt < 0
                  ? "not dropped"
                  : String.format(Locale.ROOT, "%.1f s", droppedAt / 1e9)));
      sb.append(
          String.format(Locale.ROOT, "| reason | %s |%n", c.isClosed() ? c.getCloseReason() : "-"));
      sb.append(
          String.format(
              Locale.ROOT,
              "| JVM heap in use after GC, before / after | %d / %d MB |%n",
              heapBefore >> 20,
              heapAfter >> 20));
      sb.append(
          String.format(
              Locale.ROOT,
              "| robot cycle meanwhile: p50 / p99 / max | %.2f / %.2f / %.2f ms |%n",
              during.p50(),
              during.p99(),
              during.max()));
      return sb.toString();
    }
  }

  private static ArServerClient waitForClient(ArServerBase server) throws Exception {
    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
    while (System.nanoTime() < end) {
      List<ArServerClient> l = server.getClients();
      for (ArServerClient c : l) {
        if (c.getUser().equals("stuck") && c.isLoggedIn()) {
          return c;
        }
      }
      pause(Duration.ofMillis(5));
    }
    throw new ArClientException(null, "the non-reading client did not log in");
  }

  private static long usedHeap() {
    Runtime r = Runtime.getRuntime();
    System.gc();
    return r.totalMemory() - r.freeMemory();
  }

  private static void row(StringBuilder sb, String phase, CycleStats c) {
    sb.append(
        String.format(
            Locale.ROOT,
            "| %s | %d | %.2f | %.2f | %.2f |%n",
            phase,
            c.cycles(),
            c.p50(),
            c.p99(),
            c.max()));
  }

  /** Lets real time pass (the benchmark measures real time). */
  private static void pause(Duration d) throws InterruptedException {
    TimeUnit.NANOSECONDS.sleep(d.toNanos());
  }
}
