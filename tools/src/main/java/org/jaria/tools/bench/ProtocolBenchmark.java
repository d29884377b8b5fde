package org.jaria.tools.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.jaria.clock.Clock;
import org.jaria.connection.ArTcpConnection;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.robot.ArRobot;
import org.jaria.testing.FakeRobot;

/**
 * {@code jaria bench protocol}: how fast the protocol code is, on one core.
 *
 * <ul>
 *   <li>SIPs received and decoded per second (framing, checksum and field decoding of a SIP with 16
 *       sonar readings and the usual tail), and decoded alone. Timed on the benchmark thread's CPU
 *       time where the JVM can measure it, so other programs on a busy machine do not lower the
 *       figures (they still disturb caches); otherwise on the wall clock. The table says which.
 *   <li>Bytes allocated per SIP received and decoded (should be 0: the receiver, the packet and the
 *       decoded SIP are reused).
 *   <li>Command packets and SIPs encoded per second.
 *   <li>SIP-to-command latency over loopback TCP: a scripted robot sends a SIP whose position
 *       changes; the client's cycle (packet handlers, a sensor task that changes the velocity,
 *       state reflection, 10 user tasks) answers with a VEL; the robot side times SIP written to
 *       VEL read. That round trip includes two loopback hops, so it bounds the client's own
 *       SIP-arrival-to-command-written time from above.
 * </ul>
 */
public final class ProtocolBenchmark {

  private ProtocolBenchmark() {}

  /**
   * How long the benchmark runs: {@code rounds} timed runs of {@code n} operations per rate, and
   * {@code samples} round trips.
   */
  record Effort(String name, int rounds, long n, int samples) {
    static final Effort FULL = new Effort("full", 7, 10_000_000, 3000);
    static final Effort QUICK = new Effort("quick", 3, 2_000_000, 500);
  }

  /** Runs everything and returns the table ({@code quick}: shorter, less precise runs). */
  public static String run(boolean quick) throws Exception {
    return run(quick ? Effort.QUICK : Effort.FULL);
  }

  /** Runs everything with that effort and returns the table. */
  static String run(Effort effort) throws Exception {
    StringBuilder out = new StringBuilder();
    out.append("JAria protocol benchmark (").append(effort.name()).append(")\n");
    out.append(String.format(Locale.ROOT, "%-46s %16s%n", "measure", "result"));
    int rounds = effort.rounds();
    long n = effort.n();
    out.append(String.format(Locale.ROOT, "%-46s %16s%n", "rates timed on", timerName()));
    row(out, "SIPs received+decoded per second (1 core)", rate(rounds, n, receiveAndDecode()));
    row(out, "SIPs decoded per second (1 core)", rate(rounds, n, decodeOnly()));
    row(out, "commands encoded per second (VEL)", rate(rounds, n, encodeCommands()));
    row(out, "SIPs encoded per second", rate(rounds, n, encodeSips()));
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %16s%n",
            "bytes allocated per SIP received+decoded",
            allocationPerOp(n, receiveAndDecode())));
    long[] lat = latency(effort.samples());
    out.append(
        String.format(
            Locale.ROOT,
            "%-46s %16s%n",
            "SIP->command round trip, loopback, 10 tasks",
            lat.length + " samples"));
    String[] names = {"p50", "p90", "p99", "p99.9"};
    double[] qs = {0.5, 0.9, 0.99, 0.999};
    for (int i = 0; i < qs.length; i++) {
      int at = (int) Math.min(lat.length - 1, Math.floor(qs[i] * lat.length));
      out.append(
          String.format(Locale.ROOT, "%-46s %13.1f us%n", "  " + names[i], lat[at] / 1000.0));
    }
    out.append(
        String.format(Locale.ROOT, "%-46s %13.1f us%n", "  max", lat[lat.length - 1] / 1000.0));
    return out.toString();
  }

  private static void row(StringBuilder out, String name, double perSecond) {
    out.append(String.format(Locale.ROOT, "%-46s %13.2f M/s%n", name, perSecond / 1e6));
  }

  /**
   * One benchmark body: does {@code n} operations, returns a value so nothing is optimised away.
   */
  interface Body {
    long run(long n);
  }

  /** Median rate over {@code rounds} timed runs after a warm-up. */
  private static double rate(int rounds, long n, Body body) {
    long sink = body.run(n / 4);
    double[] rates = new double[rounds];
    for (int r = 0; r < rounds; r++) {
      long t0 = now();
      sink += body.run(n);
      long t1 = now();
      rates[r] = n / (Math.max(1, t1 - t0) / 1e9);
    }
    if (sink == 42) {
      System.out.print("");
    }
    Arrays.sort(rates);
    return rates[rounds / 2];
  }

  private static final java.lang.management.ThreadMXBean THREADS =
      ManagementFactory.getThreadMXBean();

  private static boolean cpuTimed() {
    return THREADS.isCurrentThreadCpuTimeSupported() && THREADS.isThreadCpuTimeEnabled();
  }

  private static String timerName() {
    return cpuTimed() ? "thread CPU time" : "wall clock";
  }

  /** Nanoseconds on the benchmark thread's CPU clock, or on the wall clock if there is none. */
  private static long now() {
    return cpuTimed() ? THREADS.getCurrentThreadCpuTime() : System.nanoTime();
  }

  /**
   * Bytes the benchmark thread allocates per operation over {@code n} operations after a warm-up,
   * as text ("n/a" where the JVM cannot count them).
   */
  static String allocationPerOp(long n, Body body) {
    if (!(THREADS instanceof com.sun.management.ThreadMXBean counting)
        || !counting.isThreadAllocatedMemorySupported()
        || !counting.isThreadAllocatedMemoryEnabled()) {
      return "n/a";
    }
    long id = Thread.currentThread().getId();
    long sink = body.run(n / 4);
    long before = counting.getThreadAllocatedBytes(id);
    sink += body.run(n);
    long after = counting.getThreadAllocatedBytes(id);
    if (sink == 42) {
      System.out.print("");
    }
    return String.format(Locale.ROOT, "%.3f B", (after - before) / (double) n);
  }

  private static byte[] sampleSip() {
    StandardSip s = new StandardSip().setMoving(true).setPos(1234, 5678, 900);
    s.setWheelVels(300, 310).setBattery(125).setFlags(0x1F);
    for (int i = 0; i < 16; i++) {
      s.addSonar(i, 500 + 37 * i);
    }
    s.setIo(0, 1, 2, 3, 4).setPower(125, 0, 15, 0).setOptionalCount(9);
    return s.encode(new ArRobotPacket()).toByteArray();
  }

  static Body receiveAndDecode() {
    byte[] frame = sampleSip();
    StandardSip sip = new StandardSip();
    ArRobotPacketReceiver rx = new ArRobotPacketReceiver(new DropCounters("bench"));
    long[] sum = {0};
    ArRobotPacketReceiver.Listener l =
        p -> {
          if (sip.decode(p)) {
            sum[0] += sip.getSonarRange(15);
          }
        };
    return n -> {
      for (long i = 0; i < n; i++) {
        rx.feed(frame, 0, frame.length, i, l);
      }
      return sum[0];
    };
  }

  private static Body decodeOnly() {
    byte[] frame = sampleSip();
    ArRobotPacket p = new ArRobotPacket().load(frame, 0, frame.length);
    StandardSip sip = new StandardSip();
    return n -> {
      long sum = 0;
      for (long i = 0; i < n; i++) {
        sip.decode(p);
        sum += sip.getXPos();
      }
      return sum;
    };
  }

  private static Body encodeCommands() {
    ArRobotPacket p = new ArRobotPacket();
    return n -> {
      long sum = 0;
      for (long i = 0; i < n; i++) {
        CommandCodec.comInt(p, ArCommands.VEL.getNumber(), (int) (i & 1023) - 512);
        sum += p.getBuf()[p.getLength() - 1];
      }
      return sum;
    };
  }

  private static Body encodeSips() {
    StandardSip s = new StandardSip();
    for (int i = 0; i < 16; i++) {
      s.addSonar(i, 1000);
    }
    s.setOptionalCount(9);
    ArRobotPacket p = new ArRobotPacket();
    return n -> {
      long sum = 0;
      for (long i = 0; i < n; i++) {
        s.setPos((int) i, 0, 0);
        s.encode(p);
        sum += p.getLength();
      }
      return sum;
    };
  }

  /** Round-trip samples in nanoseconds, sorted. */
  private static long[] latency(int samples) throws Exception {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      CompletableFuture<long[]> samplesDone = new CompletableFuture<>();
      Thread robotSide = new Thread(() -> serve(server, samples, samplesDone), "bench-fake-robot");
      robotSide.start();
      ArRobot robot = new ArRobot("bench");
      robot.setDeviceConnection(
          new ArTcpConnection("127.0.0.1", server.getLocalPort(), Clock.system()));
      robot.setConnectionTimeoutTime(0);
      if (!robot.blockingConnect()) {
        throw new IOException("benchmark robot did not connect: " + robot.getConnectFailure());
      }
      // Odometry x is what the robot reported: answer each SIP with a velocity derived from it.
      robot.addSensorInterpTask(
          "follow x", 10, () -> robot.setVel(robot.getRawEncoderPose().x() - 900));
      long[] work = new long[10];
      for (int i = 0; i < 10; i++) {
        int k = i;
        robot.addUserTask("task " + i, i, () -> work[k] += (long) robot.getVel());
      }
      robot.runAsync(true);
      long[] result = samplesDone.get(120, TimeUnit.SECONDS);
      robot.close();
      robotSide.join(10_000);
      Arrays.sort(result);
      return result;
    }
  }

  private static void serve(ServerSocket server, int samples, CompletableFuture<long[]> done) {
    try (Socket s = server.accept()) {
      ArTcpConnection conn = ArTcpConnection.wrap(s, Clock.system());
      FakeRobot fake = new FakeRobot(conn, Clock.system());
      while (!fake.isOpen()) {
        if (!fake.pumpWait(1000)) {
          throw new IOException("client went away during the handshake");
        }
      }
      StandardSip sip = new StandardSip();
      long[] rtt = new long[samples];
      for (int i = -200; i < samples; i++) {
        int x = 1000 + (i & 0xFF);
        sip.setPos(x, 0, 0);
        int before = fake.receivedCount();
        long t0 = System.nanoTime();
        fake.sendSip(sip);
        long t1 = waitForVel(fake, before, x - 900);
        if (i >= 0) {
          rtt[i] = t1 - t0;
        }
        // give the client's cycle a moment, as a robot would (SIPs come every 100 ms)
        long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(2);
        while (System.nanoTime() < until) {
          fake.pump();
        }
      }
      done.complete(rtt);
      // Stay until the client says goodbye, as a robot would.
      while (fake.isOpen() && fake.pumpWait(100)) {
        // answering until CLOSE
      }
    } catch (IOException e) {
      done.completeExceptionally(
          new IllegalStateException("benchmark robot failed: " + e.getMessage(), e));
    }
  }

  private static long waitForVel(FakeRobot fake, int from, int vel) throws IOException {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
    int seen = from;
    while (System.nanoTime() < deadline) {
      fake.pumpWait(50);
      for (; seen < fake.receivedCount(); seen++) {
        FakeRobot.Received r = fake.received(seen);
        if (r.id() == ArCommands.VEL.getNumber() && r.intArg() == vel) {
          return r.timeNanos();
        }
      }
    }
    throw new IOException("no VEL " + vel + " within 5 s");
  }
}
