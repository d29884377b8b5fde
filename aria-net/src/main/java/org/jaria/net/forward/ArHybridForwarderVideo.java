package org.jaria.net.forward;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.time.Duration;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import org.jaria.net.ArNetPacket;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ClientOptions;
import org.jaria.net.client.ConnectionListener;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.info.VideoData;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Forwards a video server's pictures to this server's clients, as ArNetworking's {@code
 * ArHybridForwarderVideo} does in ARIA's serverDemo and ARNL's guiServer: it connects as a client
 * to the video server (ACTS's SAV server on port 7070, {@code jaria acts}, or any server offering
 * {@code sendVideo}), keeps asking it for the next frame, and offers {@code sendVideo} and {@code
 * videoSize} of its own, answered at once with the newest frame and size it has. However many
 * clients watch, the video server is asked for one frame at a time.
 *
 * <pre>{@code
 * ArServerBase server = ...;                       // or gui.getServer()
 * try (ArHybridForwarderVideo video = new ArHybridForwarderVideo(server, "localhost", 7070)) {
 *   server.open();
 *   ...
 * }
 * }</pre>
 *
 * <p>Timing is ArNetworking's: the next frame is asked for once the last one is 100 ms old ({@link
 * #setVideoRequestTime}), and a request is repeated after 3 s without an answer. Unlike ARIA's,
 * which looks for the video server once and forwards nothing if it is not running yet, this
 * forwarder offers its data from the start and keeps (re)connecting in the background, so the video
 * server may start, stop and come back in any order. Until it has a frame, and whenever it is not
 * connected, it answers a 0 × 0 frame with no bytes (what a SAV server answers before its first
 * picture). Packets that are not frames, frames nobody asked for, and a server that stops answering
 * for 10 s are dropped and counted ({@link #getStats()}); none of it touches the server's other
 * clients. One thread, "jaria-net-video-forward", talks to the video server; {@link #close()} stops
 * and joins it.
 */
public final class ArHybridForwarderVideo implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArHybridForwarderVideo.class);

  /** ArNetworking's SAV (and ACTS) video port. */
  public static final int DEFAULT_PORT = 7070;

  /** The quality asked of the video server until a client asks for another (as ARIA's). */
  static final int FIRST_QUALITY = 90;

  private static final byte[] NO_FRAME = {0, 0, 0, 0};

  private final String host;
  private final int port;
  private final ArClientBase client;
  private final LongSupplier clock;
  private final ScheduledExecutorService thread;

  private final Object lock = new Object();

  @GuardedBy("lock")
  private byte[] frame = NO_FRAME;

  @GuardedBy("lock")
  private byte[] size = NO_FRAME;

  @GuardedBy("lock")
  private int quality = FIRST_QUALITY;

  @GuardedBy("lock")
  private boolean requestOut;

  @GuardedBy("lock")
  private long lastFrameNanos;

  @GuardedBy("lock")
  private long lastRequestNanos;

  @GuardedBy("lock")
  private long intervalMs = ForwardingRules.DEFAULT_REQUEST_INTERVAL_MS;

  // Only the forwarding thread touches these three.
  private int failures;
  private long nextAttemptNanos;
  private boolean wasConnected;

  private volatile boolean forwarding;
  private final AtomicLong connects = new AtomicLong();
  private final AtomicLong failedConnects = new AtomicLong();
  private final AtomicLong lost = new AtomicLong();
  private final AtomicLong stalls = new AtomicLong();
  private final AtomicLong requests = new AtomicLong();
  private final AtomicLong frames = new AtomicLong();
  private final AtomicLong dropped = new AtomicLong();
  private final AtomicLong served = new AtomicLong();

  /**
   * Forwards the video of the server at {@code host}:{@code port} (ARIA's defaults: "localhost",
   * {@link #DEFAULT_PORT}) through {@code server}, registering {@code sendVideo} and {@code
   * videoSize} with it. Call before the server opens, so clients see them in the data list.
   *
   * @throws IllegalArgumentException if {@code server} already has video data of those names
   */
  public ArHybridForwarderVideo(ArServerBase server, String host, int port) {
    this(server, host, port, Duration.ofSeconds(2), System::nanoTime);
  }

  /**
   * As {@link #ArHybridForwarderVideo(ArServerBase, String, int)}, with the time allowed to connect
   * and log in, and the clock (nanoseconds) the request rules run on.
   */
  public ArHybridForwarderVideo(
      ArServerBase server, String host, int port, Duration connectTimeout, LongSupplier clock) {
    if (port < 1 || port > 0xFFFF) {
      throw new IllegalArgumentException("the video server's port must be 1..65535, got " + port);
    }
    this.host = host;
    this.port = port;
    this.clock = clock;
    this.client =
        new ArClientBase(
            new ClientOptions(
                "video-forward-" + host + ":" + port,
                connectTimeout,
                Duration.ofMillis(ForwardingRules.REREQUEST_MS),
                ""));
    client.addHandler("sendVideo", this::receiveVideo);
    client.addHandler("videoSize", this::receiveVideoSize);
    client.addConnectionListener(
        new ConnectionListener() {
          @Override
          public void connected(ArClientBase c) {
            // Counted and set up by the forwarding thread after connect() returns.
          }

          @Override
          public void disconnected(ArClientBase c, String why) {
            forget(why);
          }
        });
    VideoData.addVideoSize(server, (c, request, reply) -> reply.dataToBuf(sendVideoSize()));
    VideoData.addSendVideo(server, (c, request, reply) -> reply.dataToBuf(sendVideo(request)));
    synchronized (lock) {
      lastFrameNanos = clock.getAsLong();
      lastRequestNanos = lastFrameNanos;
    }
    thread =
        Executors.newSingleThreadScheduledExecutor(
            r -> {
              Thread t = new Thread(r, "jaria-net-video-forward");
              t.setDaemon(true);
              return t;
            });
    var unused = thread.scheduleWithFixedDelay(this::cycle, 0, 10, TimeUnit.MILLISECONDS);
  }

  // ------------------------------------------------------------------ serving

  /** The newest frame for a client (ArNetworking's {@code sendVideo}); remembers its quality. */
  byte[] sendVideo(ArNetPacket request) {
    synchronized (lock) {
      if (request.getRemaining() >= 1) {
        // As ARIA's forwarder, the quality the last client asked for is asked of the server next.
        quality = Math.min(100, request.bufToUByte());
      }
      served.incrementAndGet();
      return frame;
    }
  }

  /** The video's size for a client (ArNetworking's {@code videoSize}). */
  byte[] sendVideoSize() {
    synchronized (lock) {
      served.incrementAndGet();
      return size;
    }
  }

  // ------------------------------------------------------------------ receiving

  /** A frame from the video server (ArNetworking's {@code receiveVideo}). */
  void receiveVideo(ArNetPacket p) {
    byte[] body = p.remainingBytes();
    String why = VideoPacketCheck.whyNotAFrame(body);
    synchronized (lock) {
      if (why == null && !requestOut) {
        why = "a frame nobody asked for";
      }
      if (why != null) {
        countDrop(why);
        return;
      }
      frame = body;
      requestOut = false;
      lastFrameNanos = clock.getAsLong();
    }
    frames.incrementAndGet();
  }

  /** The video's size from the video server (ArNetworking's {@code receiveVideoSize}). */
  void receiveVideoSize(ArNetPacket p) {
    byte[] body = p.remainingBytes();
    String why = VideoPacketCheck.whyNotASize(body);
    if (why != null) {
      countDrop(why);
      return;
    }
    synchronized (lock) {
      size = java.util.Arrays.copyOf(body, 4);
    }
  }

  private void countDrop(String why) {
    if (dropped.getAndIncrement() % 100 == 0) {
      log.warn("video from {}:{} dropped: {}", host, port, why);
    }
  }

  /** The connection is gone: no more stale pictures for clients. */
  private void forget(String why) {
    synchronized (lock) {
      frame = NO_FRAME;
      size = NO_FRAME;
      requestOut = false;
    }
    if (forwarding) {
      forwarding = false;
      lost.incrementAndGet();
      log.info("video server {}:{} lost ({}); connecting again", host, port, why);
    }
  }

  // ------------------------------------------------------------------ the forwarding thread

  private void cycle() {
    try {
      long now = clock.getAsLong();
      if (!client.isConnected()) {
        if (wasConnected) {
          // Lost: wait a little before connecting again, so that a server that takes the
          // connection and drops it at once is not hammered.
          wasConnected = false;
          failures = 1;
          nextAttemptNanos = now + ForwardingRules.reconnectDelayMs(failures) * 1_000_000;
        }
        if (now - nextAttemptNanos >= 0) {
          tryConnect();
        }
        return;
      }
      boolean ask;
      boolean stalled;
      synchronized (lock) {
        long sinceFrame = (now - lastFrameNanos) / 1_000_000;
        long sinceRequest = (now - lastRequestNanos) / 1_000_000;
        stalled = ForwardingRules.isStalled(requestOut, sinceFrame);
        ask =
            !stalled
                && ForwardingRules.shouldRequest(sinceFrame, requestOut, sinceRequest, intervalMs);
        if (ask) {
          requestOut = true;
          lastRequestNanos = now;
        }
      }
      if (stalled) {
        stalls.incrementAndGet();
        log.warn("video server {}:{} stopped answering; connecting again", host, port);
        client.disconnect();
      } else if (ask) {
        askForFrame();
      }
    } catch (RuntimeException e) {
      // The schedule would stop on an exception: log it and go on.
      log.warn("video forwarder cycle failed", e);
    }
  }

  private void askForFrame() {
    int q;
    synchronized (lock) {
      q = quality;
    }
    ArNetPacket args = new ArNetPacket().uByteToBuf(q);
    var unused = client.requestOnce("sendVideo", args);
    requests.incrementAndGet();
  }

  private void tryConnect() {
    long now = clock.getAsLong();
    if (client.blockingConnect(host, port, "", "")) {
      if (!client.dataExists("sendVideo")) {
        log.warn("{}:{} offers no sendVideo: it is not a video server", host, port);
        client.disconnect();
        failed(now);
        return;
      }
      failures = 0;
      wasConnected = true;
      connects.incrementAndGet();
      synchronized (lock) {
        requestOut = false;
        lastFrameNanos = now - ForwardingRules.DEFAULT_REQUEST_INTERVAL_MS * 2_000_000;
        lastRequestNanos = now;
      }
      forwarding = true;
      log.info("forwarding video from {}:{}", host, port);
      if (client.dataExists("videoSize")) {
        var unused = client.requestOnce("videoSize", (ArNetPacket) null);
      }
    } else {
      failed(now);
    }
  }

  private void failed(long now) {
    failures++;
    failedConnects.incrementAndGet();
    if (failures == 1 || failures % 20 == 0) {
      log.info("no video server at {}:{} ({}); trying again", host, port, client.getLastError());
    }
    nextAttemptNanos = now + ForwardingRules.reconnectDelayMs(failures) * 1_000_000;
  }

  // ------------------------------------------------------------------ ARIA's accessors

  /** Whether it is connected to a video server that offers video (ArNetworking's name). */
  public boolean isForwardingVideo() {
    return forwarding && client.isConnected();
  }

  /** Sets how long after a frame the next is asked for (ms; ArNetworking's default 100). */
  public void setVideoRequestTime(long ms) {
    if (ms < 0) {
      throw new IllegalArgumentException("the video request time must be >= 0 ms, got " + ms);
    }
    synchronized (lock) {
      intervalMs = ms;
    }
  }

  /** How long after a frame the next is asked for (ms). */
  public long getVideoRequestTime() {
    synchronized (lock) {
      return intervalMs;
    }
  }

  /** What it has done so far. */
  public ForwarderStats getStats() {
    return new ForwarderStats(
        isForwardingVideo(),
        connects.get(),
        failedConnects.get(),
        lost.get(),
        stalls.get(),
        requests.get(),
        frames.get(),
        dropped.get(),
        served.get());
  }

  /** Where the video comes from ("host:port"). */
  public String getSource() {
    return host + ":" + port;
  }

  /** Stops forwarding: disconnects from the video server and joins the thread. */
  @Override
  public void close() {
    thread.shutdown();
    client.disconnect();
    try {
      if (!thread.awaitTermination(5, TimeUnit.SECONDS)) {
        thread.shutdownNow();
        log.warn("the video forwarding thread did not stop within 5 s");
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    client.close();
  }
}
