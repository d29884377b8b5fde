package org.jaria.tools.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.map.ArMap;
import org.jaria.net.ArNetPacket;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ArClientException;
import org.jaria.net.server.Authenticator;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.ServerStats;
import org.jaria.simguiserver.SimulatedGuiServer;

/**
 * The guiServer's rows of {@code jaria bench hostile}: while hostile clients on the loopback attack
 * a guiServer (with a password, on an embedded simulator in real time), a real user logs in or asks
 * for {@code update} again and again — is it served? — and the robot's cycle time is measured
 * meanwhile (its 99th percentile, against the 100 ms budget). Attacks: silent sockets that squat
 * the login slots and renew themselves (from one address, and from many), and a logged-in user who
 * sends goal names of 31,900 characters.
 */
public final class GuiServerHostileBenchmark {

  private static final String PASSWORD = "bench-secret";

  private GuiServerHostileBenchmark() {}

  /** Runs the attacks and returns their rows. */
  public static String run(boolean quick) throws Exception {
    int tries = quick ? 5 : 30;
    StringBuilder out = new StringBuilder();
    out.append(
        String.format(
            Locale.ROOT,
            "%n%-44s %14s %14s %s%n",
            "guiServer scenario",
            "real served",
            "cycle p99 ms",
            "server's counts"));
    ServerOptions so =
        ServerOptions.builder()
            .port(0)
            .bindAddress("127.0.0.1")
            .authenticator(Authenticator.sharedSecret(PASSWORD))
            .build();
    try (SimulatedGuiServer s =
        SimulatedGuiServer.start(
            new SimulatedGuiServer.Options(
                ArMap.loadBundled("office"),
                "office.map",
                "p3dx-sh",
                1,
                so,
                ArnlNavigation.Mode.THREADED,
                1.0,
                false))) {
      Cycles cycles = new Cycles(s);
      try {
        squatters(out, s, cycles, "8 login squatters renewing, one address", 8, 1, tries);
        squatters(out, s, cycles, "64 login squatters over 16 addresses", 64, 16, tries);
        longStrings(out, s, cycles, tries);
      } finally {
        cycles.close();
      }
    }
    return out.toString();
  }

  /**
   * {@code n} silent sockets from {@code addresses} loopback addresses, each renewed about every
   * half second (the 1.8 a second), while a real user logs in {@code tries} times.
   */
  private static void squatters(
      StringBuilder out,
      SimulatedGuiServer s,
      Cycles cycles,
      String what,
      int n,
      int addresses,
      int tries)
      throws Exception {
    AtomicBoolean stop = new AtomicBoolean();
    List<Thread> threads = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      String from = "127.0.0." + (addresses == 1 ? 1 : 2 + i % addresses);
      long renewMs = 400 + (i * 37L) % 300;
      Thread t = new Thread(() -> squat(s.port(), from, renewMs, stop), "bench-squatter-" + i);
      t.setDaemon(true);
      t.start();
      threads.add(t);
    }
    ServerStats st = s.gui().getServer().getStats();
    long replaced0 = st.getReplacedPending();
    long refused0 = st.getRefusedPending();
    try {
      pause(Duration.ofSeconds(2));
      cycles.reset();
      int served = 0;
      for (int i = 0; i < tries; i++) {
        try (ArClientBase real = new ArClientBase("real-user")) {
          real.connect("127.0.0.1", s.port(), "operator", PASSWORD);
          served++;
        } catch (ArClientException e) {
          // not served
        }
        pause(Duration.ofMillis(300));
      }
      row(
          out,
          what,
          served,
          tries,
          cycles.p99(),
          String.format(
              Locale.ROOT,
              "%d replaced, %d refused",
              st.getReplacedPending() - replaced0,
              st.getRefusedPending() - refused0));
    } finally {
      stop.set(true);
      for (Thread t : threads) {
        t.join(TimeUnit.SECONDS.toMillis(5));
      }
    }
  }

  /** One squatter: connects, says nothing, and connects again every {@code renewMs}. */
  private static void squat(int port, String from, long renewMs, AtomicBoolean stop) {
    while (!stop.get()) {
      try (Socket sock = new Socket()) {
        sock.bind(new InetSocketAddress(InetAddress.getByName(from), 0));
        sock.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 2000);
        pause(Duration.ofMillis(renewMs));
      } catch (IOException e) {
        pause(Duration.ofMillis(50));
      }
    }
  }

  /**
   * A logged-in user sends {@code gotoGoal} with a 31,900-character name ten times a second while a
   * real user asks for {@code update} {@code tries} times: served if it answers, and small.
   */
  private static void longStrings(StringBuilder out, SimulatedGuiServer s, Cycles cycles, int tries)
      throws Exception {
    AtomicBoolean stop = new AtomicBoolean();
    AtomicLong refusals = new AtomicLong();
    String name = "G".repeat(31_900);
    Thread attacker =
        new Thread(
            () -> {
              try (ArClientBase bad = new ArClientBase("long-strings")) {
                bad.connect("127.0.0.1", s.port(), "vandal", PASSWORD);
                while (!stop.get()) {
                  var unused =
                      bad.requestOnce("gotoGoal", name)
                          .whenComplete((r, e) -> refusals.addAndGet(e != null ? 1 : 0));
                  pause(Duration.ofMillis(100));
                }
              } catch (ArClientException e) {
                // the row shows that nothing was refused, or says so
              }
            },
            "bench-long-strings");
    attacker.setDaemon(true);
    attacker.start();
    int served = 0;
    int largest = 0;
    try (ArClientBase real = new ArClientBase("real-monitor")) {
      real.connect("127.0.0.1", s.port(), "operator", PASSWORD);
      pause(Duration.ofSeconds(2));
      cycles.reset();
      for (int i = 0; i < tries; i++) {
        try {
          ArNetPacket u = real.requestOnce("update").get(5, TimeUnit.SECONDS);
          largest = Math.max(largest, u.getDataLength());
          if (u.getDataLength() < 1000) {
            served++;
          }
        } catch (java.util.concurrent.ExecutionException
            | java.util.concurrent.TimeoutException e) {
          // not served
        }
        pause(Duration.ofMillis(300));
      }
    } finally {
      stop.set(true);
      attacker.join(TimeUnit.SECONDS.toMillis(5));
    }
    row(
        out,
        "long-string user (31,900-char goal names)",
        served,
        tries,
        cycles.p99(),
        String.format(
            Locale.ROOT, "update at most %d B, %d goals refused", largest, refusals.get()));
  }

  private static void row(
      StringBuilder out, String what, int served, int tries, double p99, String counts) {
    out.append(
        String.format(
            Locale.ROOT, "%-44s %14s %14.2f %s%n", what, served + " of " + tries, p99, counts));
  }

  private static void pause(Duration d) {
    try {
      TimeUnit.NANOSECONDS.sleep(d.toNanos());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** The robot's cycle times, recorded after each world step that ran a cycle. */
  private static final class Cycles {
    private final SimulatedGuiServer s;
    private final Runnable listener = this::afterStep;
    private long lastCounter;
    private long[] samples = new long[1024];
    private int n;

    Cycles(SimulatedGuiServer s) {
      this.s = s;
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

    synchronized double p99() {
      if (n == 0) {
        return Double.NaN;
      }
      long[] sorted = Arrays.copyOf(samples, n);
      Arrays.sort(sorted);
      int i = (int) Math.ceil(0.99 * n) - 1;
      return sorted[Math.max(0, Math.min(n - 1, i))] / 1e6;
    }

    void close() {
      s.world().removeStepListener(listener);
    }
  }
}
