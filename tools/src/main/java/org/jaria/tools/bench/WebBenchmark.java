package org.jaria.tools.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.map.ArMap;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.server.Authenticator;
import org.jaria.net.server.ServerOptions;
import org.jaria.range.ArSimulatedLaser;
import org.jaria.robot.ArRobot;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.jaria.tools.web.NavigationView;
import org.jaria.web.server.WebOptions;
import org.jaria.web.server.WebServer;

/**
 * {@code jaria bench web}: the web view under load. A p3dx-sh on the office map in real time, with
 * its 16 sonars, a 181-beam laser and SonARNL's 2000 particles; first alone, then with the web
 * server publishing at 10 Hz to 10 WebSocket clients subscribed to every channel (as the page and
 * Foxglove subscribe). Measures the server's CPU (its publisher and Jetty threads), the latency
 * from a frame's sampling to its arrival at a client, the robot's cycle with and without the
 * server, and the bytes each client receives.
 */
public final class WebBenchmark {

  private static final Pattern CLOCK_TOPIC = Pattern.compile("\"id\":(\\d+),\"topic\":\"/clock\"");

  private WebBenchmark() {}

  /** Runs it; {@code quick} shortens each phase from 20 s to 6 s. */
  public static String run(boolean quick) throws Exception {
    int seconds = quick ? 6 : 20;
    int clients = 10;
    ArMap map = ArMap.loadBundled("office");
    ServerOptions monitors =
        ServerOptions.builder()
            .serverName("bench")
            .port(0)
            .bindAddress("127.0.0.1")
            .authenticator(Authenticator.open())
            .build();
    try (SimulatedGuiServer s =
        SimulatedGuiServer.start(
            new SimulatedGuiServer.Options(
                map, "office", "p3dx-sh", 1, monitors, ArnlNavigation.Mode.THREADED, 1, false))) {
      ArRobot robot = s.robot();
      robot.lock();
      try {
        robot.addRangeDevice(new ArSimulatedLaser());
      } finally {
        robot.unlock();
      }
      CycleRecorder cycles = new CycleRecorder(robot);
      NavigationView nv =
          NavigationView.simulated(s.world(), s.sim().sim().getName(), s.nav(), map, "office", 1);
      // wander so that localization, sonar and laser all work as they do while driving
      nv.driver().goTo(new org.jaria.geom.ArPose(26000, 9500), false);
      TimeUnit.SECONDS.sleep(2);
      cycles.reset();
      TimeUnit.SECONDS.sleep(seconds);
      long[] alone = cycles.take();

      WebOptions o = WebOptions.loopback(0).withLimits(16, 65536, 4 << 20, 3000);
      try (WebServer web = WebServer.start(o, nv.source(), nv.controls())) {
        Map<Long, Long> sampled = new ConcurrentHashMap<>();
        web.setFrameObserver((t, at) -> sampled.put(t, at));
        List<Client> cs = new ArrayList<>();
        for (int i = 0; i < clients; i++) {
          cs.add(new Client(web.websocketUrl(), sampled));
        }
        TimeUnit.SECONDS.sleep(2);
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        long cpu0 = webCpu(mx);
        long t0 = System.nanoTime();
        cs.forEach(Client::reset);
        cycles.reset();
        TimeUnit.SECONDS.sleep(seconds);
        long[] loaded = cycles.take();
        long wall = System.nanoTime() - t0;
        long cpu = webCpu(mx) - cpu0;
        List<Long> lat = new ArrayList<>();
        long bytes = 0;
        for (Client c : cs) {
          lat.addAll(c.latencies);
          bytes += c.bytes.get();
          c.ws.abort();
        }
        long[] latency = lat.stream().mapToLong(Long::longValue).toArray();
        nv.driver().close();
        return table(quick, seconds, clients, alone, loaded, latency, cpu, wall, bytes, web, s);
      }
    }
  }

  private static String table(
      boolean quick,
      int seconds,
      int clients,
      long[] alone,
      long[] loaded,
      long[] latency,
      long cpu,
      long wall,
      long bytes,
      WebServer web,
      SimulatedGuiServer s) {
    StringBuilder out = new StringBuilder();
    var st = web.stats();
    out.append(
        String.format(
            Locale.ROOT,
            "JAria web view benchmark (%s, %d s a phase): p3dx-sh, office map, real time; 16 sonars,"
                + " a %d-beam laser, %d particles; %d clients at %.0f Hz subscribed to every"
                + " channel; %d cores%n",
            quick ? "quick" : "full",
            seconds,
            181,
            s.nav().getLocalizationTask().getCurrentNumSamples(),
            clients,
            web.options().rateHz(),
            Runtime.getRuntime().availableProcessors()));
    out.append(
        String.format(Locale.ROOT, "%-46s %12s %12s %9s%n", "measure", "median", "p99", "samples"));
    row(out, "robot cycle, no web server", alone, 1e-3, "us");
    row(out, "robot cycle, web server + clients", loaded, 1e-3, "us");
    row(out, "update latency (frame taken -> client)", latency, 1e-6, "ms");
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %12s%n",
            "robot cycle p99, extra with the server",
            String.format(Locale.ROOT, "%.1f us", (p(loaded, 0.99) - p(alone, 0.99)) / 1e3)));
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %12s%n",
            "server CPU (publisher + Jetty threads)",
            String.format(Locale.ROOT, "%.1f %% of a core", 100.0 * cpu / wall)));
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %12s%n",
            "bytes per second per client",
            String.format(Locale.ROOT, "%.0f kB/s", bytes / (wall / 1e9) / clients / 1000)));
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %12s%n",
            "messages dropped / slow clients closed",
            st.messagesDropped() + " / " + st.slowClientsClosed()));
    return out.toString();
  }

  private static void row(StringBuilder out, String what, long[] v, double scale, String unit) {
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %9.2f %s %9.2f %s %9d%n",
            what,
            p(v, 0.5) * scale,
            unit,
            p(v, 0.99) * scale,
            unit,
            v.length));
  }

  private static double p(long[] v, double q) {
    if (v.length == 0) {
      return Double.NaN;
    }
    long[] s = v.clone();
    Arrays.sort(s);
    return s[(int) Math.min(s.length - 1, Math.floor(q * s.length))];
  }

  /** CPU time of the web server's threads (its publisher and Jetty's pool), ns. */
  private static long webCpu(ThreadMXBean mx) {
    long sum = 0;
    for (ThreadInfo ti : mx.getThreadInfo(mx.getAllThreadIds())) {
      if (ti != null
          && (ti.getThreadName().startsWith("web-server")
              || ti.getThreadName().startsWith("web-publisher"))) {
        long t = mx.getThreadCpuTime(ti.getThreadId());
        sum += Math.max(t, 0);
      }
    }
    return sum;
  }

  /** The robot's cycle times, read each cycle from the cycle itself. */
  private static final class CycleRecorder {
    private final List<Long> samples = new ArrayList<>();
    private boolean on;

    CycleRecorder(ArRobot robot) {
      robot.addUserTask(
          "bench cycle time",
          1,
          () -> {
            synchronized (this) {
              if (on) {
                samples.add(robot.getLastCycleNanos());
              }
            }
          });
    }

    synchronized void reset() {
      samples.clear();
      on = true;
    }

    synchronized long[] take() {
      on = false;
      return samples.stream().mapToLong(Long::longValue).toArray();
    }
  }

  /** A browser-like client: subscribes to every channel, times the clock's messages. */
  private static final class Client implements WebSocket.Listener {
    final WebSocket ws;
    final Map<Long, Long> sampled;
    final List<Long> latencies = new java.util.concurrent.CopyOnWriteArrayList<>();
    final AtomicLong bytes = new AtomicLong();
    private final StringBuilder text = new StringBuilder();
    private volatile long clockSub = -1;
    private volatile boolean counting;
    private int nextSub = 1;

    Client(URI uri, Map<Long, Long> sampled) throws Exception {
      this.sampled = sampled;
      ws =
          HttpClient.newHttpClient()
              .newWebSocketBuilder()
              .subprotocols("foxglove.websocket.v1")
              .buildAsync(uri, this)
              .get(20, TimeUnit.SECONDS);
    }

    void reset() {
      latencies.clear();
      bytes.set(0);
      counting = true;
    }

    @Override
    public void onOpen(WebSocket webSocket) {
      webSocket.request(1);
    }

    @Override
    public CompletionStage<?> onText(WebSocket w, CharSequence data, boolean last) {
      text.append(data);
      if (last) {
        String s = text.toString();
        text.setLength(0);
        if (counting) {
          bytes.addAndGet(s.length());
        }
        if (s.contains("\"op\":\"advertise\"")) {
          subscribeAll(w, s);
        }
      }
      w.request(1);
      return null;
    }

    private void subscribeAll(WebSocket w, String advertise) {
      Matcher ids = Pattern.compile("\\{\"id\":(\\d+),\"topic\"").matcher(advertise);
      Matcher clock = CLOCK_TOPIC.matcher(advertise);
      long clockChannel = clock.find() ? Long.parseLong(clock.group(1)) : -1;
      StringBuilder sb = new StringBuilder("{\"op\":\"subscribe\",\"subscriptions\":[");
      boolean first = true;
      while (ids.find()) {
        long channel = Long.parseLong(ids.group(1));
        int sub = nextSub++;
        if (channel == clockChannel) {
          clockSub = sub;
        }
        sb.append(first ? "" : ",").append("{\"id\":").append(sub).append(",\"channelId\":");
        sb.append(channel).append('}');
        first = false;
      }
      var unused = w.sendText(sb.append("]}"), true);
    }

    @Override
    public CompletionStage<?> onBinary(WebSocket w, ByteBuffer data, boolean last) {
      long now = System.nanoTime();
      if (counting) {
        bytes.addAndGet(data.remaining());
      }
      ByteBuffer b = data.duplicate().order(ByteOrder.LITTLE_ENDIAN);
      if (b.remaining() >= 13 && b.get(0) == 1 && (b.getInt(1) & 0xFFFFFFFFL) == clockSub) {
        Long at = sampled.get(b.getLong(5));
        if (at != null && counting) {
          latencies.add(now - at);
        }
      }
      w.request(1);
      return null;
    }
  }
}
