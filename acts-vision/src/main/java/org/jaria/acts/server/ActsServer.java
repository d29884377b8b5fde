package org.jaria.acts.server;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.clock.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The ACTS server: tracks blobs on the latest frame of an image source and answers clients that
 * speak ACTS's wire protocol ({@link ActsProtocol}), such as {@link org.jaria.acts.ArACTS_1_2}.
 *
 * <p>Threads, all named {@code acts-<port>-...}, all stopped and joined by {@link #stop()}:
 *
 * <ul>
 *   <li>{@code pipeline}: reads a frame, tracks it, encodes the reply and publishes it, at most
 *       {@link ServerSettings#maxFps()} times a second (a still image is simply re-tracked, which
 *       also picks up channel changes made meanwhile);
 *   <li>{@code accept}: accepts clients and, at least once a second, disconnects clients idle for
 *       {@link ServerSettings#idleTimeoutMillis()} (they neither asked for blobs nor took a reply:
 *       clients that only connect, send only garbage, stop reading, or vanished without closing).
 *       When the server is full ({@link ServerSettings#maxClients()}) a newcomer replaces the
 *       client idle longest among those that never asked for blobs or have been idle half the idle
 *       timeout (at most 5 s; see {@link IdleClients}); if every client is busy, the newcomer is
 *       refused (closed at once, counted, logged at most once every 10 s).
 *   <li>{@code client-N}: one per client; answers each {@code '0'} with the latest reply, ignores
 *       (and counts) any other byte except {@code '1'} (quit). Garbage is not activity. A client
 *       that vanishes, sends garbage or stops reading only ever blocks its own thread, until it is
 *       dropped as idle.
 * </ul>
 *
 * <p>The server listens on {@link ServerSettings#bindHost()}: this computer only by default ({@code
 * 127.0.0.1}); {@code 0.0.0.0} opens it to every interface, as ACTS does.
 */
public final class ActsServer implements AutoCloseable {

  private static final Logger LOG = LoggerFactory.getLogger(ActsServer.class);
  private static final long JOIN_MS = 5000;

  /**
   * A full server may replace a client idle this long (half the idle timeout, at most this), or one
   * that never sent a byte.
   */
  private static final long EVICT_IDLE_MAX_NANOS = TimeUnit.SECONDS.toNanos(5);

  /** At most one line about refused clients this often. */
  private static final long REFUSAL_LOG_NANOS = TimeUnit.SECONDS.toNanos(10);

  private final VisionPipeline pipeline;
  private final ServerSettings settings;
  private final Clock clock;

  private final ReentrantLock lock = new ReentrantLock();
  private final Condition changed = lock.newCondition();

  @GuardedBy("lock")
  private long frames;

  @GuardedBy("lock")
  private boolean stopped;

  @GuardedBy("lock")
  private boolean stopRequested;

  @GuardedBy("lock")
  private BlobFrame latest = new BlobFrame();

  // Read by the client threads on every request without the lock: volatile, not guarded.
  private volatile byte[] reply;
  private volatile boolean running;
  private volatile ServerSocket serverSocket;
  private volatile int port = -1;

  @GuardedBy("lock")
  private Thread pipelineThread;

  @GuardedBy("lock")
  private Thread acceptThread;

  private final Set<Client> clients = ConcurrentHashMap.newKeySet();

  @GuardedBy("lock")
  private final List<Thread> clientThreads = new ArrayList<>();

  @GuardedBy("lock")
  private int clientCounter;

  private final AtomicLong requests = new AtomicLong();
  private final AtomicLong garbage = new AtomicLong();
  private final AtomicLong accepted = new AtomicLong();
  private final AtomicLong refused = new AtomicLong();
  private final AtomicLong droppedIdle = new AtomicLong();
  private final AtomicLong replaced = new AtomicLong();

  // The accept thread's, under the lock (see refuse).
  @GuardedBy("lock")
  private long lastRefusalLogNanos;

  @GuardedBy("lock")
  private long refusalsNotLogged;

  @GuardedBy("lock")
  private boolean refusalLogged;

  private final AtomicLong sourceErrors = new AtomicLong();

  /** A server (not yet started) for a pipeline. */
  public ActsServer(VisionPipeline pipeline, ServerSettings settings, Clock clock) {
    if (pipeline.width() > ActsProtocol.MAX_2_DIGITS
        || pipeline.height() > ActsProtocol.MAX_2_DIGITS) {
      throw new IllegalArgumentException(
          "ACTS's protocol sends coordinates as 12-bit numbers: the image must be at most 4095"
              + " pixels on each side, got "
              + pipeline.width()
              + "x"
              + pipeline.height());
    }
    this.pipeline = pipeline;
    this.settings = settings;
    this.clock = clock;
    BlobFrame empty = new BlobFrame();
    empty.clear(pipeline.width(), pipeline.height());
    latest = empty;
    reply = ActsReply.encode(empty);
  }

  /**
   * Binds the port and starts the threads.
   *
   * @throws IOException if the port cannot be bound (the message says which and what to try)
   */
  public void start() throws IOException {
    lock.lock();
    try {
      if (running || stopped) {
        throw new IllegalStateException("an ActsServer can be started once");
      }
      ServerSocket ss = new ServerSocket();
      try {
        InetAddress addr =
            settings.bindHost().isEmpty() ? null : InetAddress.getByName(settings.bindHost());
        // a burst of connects waits in the system's queue, not for its SYN retries
        ss.bind(new InetSocketAddress(addr, settings.port()), 256);
      } catch (IOException e) {
        ss.close();
        throw new IOException(
            "cannot listen on port "
                + settings.port()
                + " ("
                + e.getMessage()
                + "): another ACTS server may be running; stop it or choose another port with -p",
            e);
      }
      // accept() wakes up at least once a second to drop idle clients
      ss.setSoTimeout(Math.max(10, Math.min(1000, settings.idleTimeoutMillis() / 4)));
      serverSocket = ss;
      port = ss.getLocalPort();
      running = true;
      pipelineThread = new Thread(this::pipelineLoop, "acts-" + port + "-pipeline");
      acceptThread = new Thread(this::acceptLoop, "acts-" + port + "-accept");
      pipelineThread.start();
      acceptThread.start();
    } finally {
      lock.unlock();
    }
    LOG.info("ACTS server listening on port {} ({})", port, pipeline.source().describe());
  }

  /** The port the server listens on (after {@link #start()}). */
  public int getPort() {
    return port;
  }

  /** The address clients should use, e.g. {@code 0.0.0.0:5001}. */
  public String getAddress() {
    ServerSocket ss = serverSocket;
    return ss == null ? "(not started)" : ss.getInetAddress().getHostAddress() + ":" + port;
  }

  // ---------------------------------------------------------------- pipeline

  private void pipelineLoop() {
    BlobFrame frame = new BlobFrame();
    byte[] buf = new byte[ActsProtocol.MAX_REPLY];
    long period = settings.maxFps() > 0 ? TimeUnit.SECONDS.toNanos(1) / settings.maxFps() : 0;
    long next = clock.nanoTime();
    try {
      while (running) {
        boolean more;
        try {
          more = pipeline.processNext(frame);
        } catch (IOException | RuntimeException e) {
          if (sourceErrors.getAndIncrement() == 0) {
            LOG.error(
                "ACTS: cannot get a frame from {}: {}", pipeline.source().describe(), e.toString());
          }
          clock.sleepMillis(1000);
          continue;
        }
        if (!more) {
          LOG.info(
              "ACTS: {} has no more frames; serving the last one", pipeline.source().describe());
          return;
        }
        int n = ActsReply.encode(frame, buf);
        byte[] r = new byte[n];
        System.arraycopy(buf, 0, r, 0, n);
        lock.lock();
        try {
          frame.setFrameNumber(++frames);
          latest = frame.copy();
          reply = r;
          changed.signalAll();
        } finally {
          lock.unlock();
        }
        if (period > 0) {
          next += period;
          long now = clock.nanoTime();
          if (next > now) {
            clock.sleepNanos(next - now);
          } else {
            next = now; // fell behind: do not try to catch up with a burst
          }
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt(); // stop() interrupts a sleeping pipeline
    }
  }

  // ---------------------------------------------------------------- clients

  private void acceptLoop() {
    while (running) {
      Socket s;
      try {
        s = serverSocket.accept();
      } catch (SocketTimeoutException e) {
        dropIdleClients();
        continue;
      } catch (IOException e) {
        if (running) {
          LOG.warn("ACTS: accept failed: {}", e.getMessage());
        }
        return;
      }
      dropIdleClients();
      lock.lock();
      try {
        if (running && clients.size() >= settings.maxClients()) {
          makeRoom();
        }
        if (!running || clients.size() >= settings.maxClients()) {
          refuse(s);
          continue;
        }
        Client c = new Client(s, clock.nanoTime());
        clients.add(c);
        accepted.incrementAndGet();
        clientCounter++;
        Thread t = new Thread(c, "acts-" + port + "-client-" + clientCounter);
        clientThreads.removeIf(th -> !th.isAlive());
        clientThreads.add(t);
        t.start();
      } finally {
        lock.unlock();
      }
    }
  }

  /** Disconnects clients idle past the idle timeout (their threads then end). */
  private void dropIdleClients() {
    List<Client> list = new ArrayList<>(clients);
    List<IdleClients.View> views = new ArrayList<>(list.size());
    for (Client c : list) {
      views.add(c.view());
    }
    long timeout = TimeUnit.MILLISECONDS.toNanos(settings.idleTimeoutMillis());
    for (int i : IdleClients.expired(views, clock.nanoTime(), timeout)) {
      Client c = list.get(i);
      if (clients.remove(c)) {
        droppedIdle.incrementAndGet();
        LOG.info("ACTS: client {} idle too long; disconnected", c.socket.getRemoteSocketAddress());
        closeQuietly(c.socket);
      }
    }
  }

  /** A full server: disconnects the client {@link IdleClients#toEvict} names, if any. */
  private void makeRoom() {
    List<Client> list = new ArrayList<>(clients);
    List<IdleClients.View> views = new ArrayList<>(list.size());
    for (Client c : list) {
      views.add(c.view());
    }
    long evictIdle =
        Math.min(
            EVICT_IDLE_MAX_NANOS, TimeUnit.MILLISECONDS.toNanos(settings.idleTimeoutMillis()) / 2);
    int i = IdleClients.toEvict(views, clock.nanoTime(), evictIdle);
    if (i >= 0 && clients.remove(list.get(i))) {
      replaced.incrementAndGet();
      LOG.debug( // a flood replaces clients by the hundred: counted, not logged one by one
          "ACTS: server full; idle client {} makes room for a new one",
          list.get(i).socket.getRemoteSocketAddress());
      closeQuietly(list.get(i).socket);
    }
  }

  /** Closes a client the full server cannot take; logged at most once every 10 s. */
  @GuardedBy("lock")
  private void refuse(Socket s) {
    refused.incrementAndGet();
    long now = clock.nanoTime();
    if (refusalLogged && now - lastRefusalLogNanos < REFUSAL_LOG_NANOS) {
      refusalsNotLogged++;
    } else {
      LOG.warn(
          "ACTS: refusing client {}: already {} busy clients (the maximum){}",
          s.getRemoteSocketAddress(),
          clients.size(),
          refusalsNotLogged > 0
              ? "; " + refusalsNotLogged + " more refused since the last line"
              : "");
      refusalLogged = true;
      lastRefusalLogNanos = now;
      refusalsNotLogged = 0;
    }
    closeQuietly(s);
  }

  /** One connected client. */
  private final class Client implements Runnable {
    final Socket socket;
    private volatile long lastActivityNanos;
    private volatile boolean asked;

    Client(Socket socket, long now) {
      this.socket = socket;
      this.lastActivityNanos = now;
    }

    IdleClients.View view() {
      return new IdleClients.View(lastActivityNanos, asked);
    }

    @Override
    public void run() {
      try {
        socket.setTcpNoDelay(true);
        // a read that waits this long means the client is idle (or gone without a word)
        socket.setSoTimeout(settings.idleTimeoutMillis());
        InputStream in = socket.getInputStream();
        OutputStream out = socket.getOutputStream();
        byte[] buf = new byte[64];
        while (running) {
          int n = in.read(buf);
          if (n < 0) {
            return;
          }
          for (int i = 0; i < n; i++) {
            if (buf[i] == ActsProtocol.REQUEST_PACKET) {
              // only a request is activity: garbage, however steady, leaves the client idle
              asked = true;
              lastActivityNanos = clock.nanoTime();
              byte[] r = reply;
              // Counted before the answer leaves: a client that has read its answer must find
              // it counted (counting after the write raced a client's check, seen once).
              requests.incrementAndGet();
              out.write(r, 0, r.length);
              lastActivityNanos = clock.nanoTime();
            } else if (buf[i] == ActsProtocol.REQUEST_QUIT) {
              LOG.info("ACTS: client {} asked to quit", socket.getRemoteSocketAddress());
              if (settings.quitOnRequest()) {
                requestStop();
              }
              return;
            } else {
              garbage.incrementAndGet();
            }
          }
        }
      } catch (SocketTimeoutException e) {
        if (clients.remove(this)) {
          droppedIdle.incrementAndGet();
        }
        LOG.info("ACTS: client {} idle too long; disconnected", socket.getRemoteSocketAddress());
      } catch (SocketException e) {
        LOG.debug("ACTS: client {} gone: {}", socket.getRemoteSocketAddress(), e.getMessage());
      } catch (IOException e) {
        LOG.debug("ACTS: client {} failed: {}", socket.getRemoteSocketAddress(), e.getMessage());
      } finally {
        closeQuietly(socket);
        clients.remove(this);
      }
    }
  }

  private static void closeQuietly(Socket s) {
    try {
      s.close();
    } catch (IOException ignored) {
      // closing anyway
    }
  }

  // ---------------------------------------------------------------- results and waiting

  /** A copy of the latest tracked frame (empty before the first). */
  public BlobFrame latestFrame() {
    lock.lock();
    try {
      return latest.copy();
    } finally {
      lock.unlock();
    }
  }

  /** The reply a {@code '0'} request gets now. */
  public byte[] latestReply() {
    return reply.clone();
  }

  /** Frames tracked so far. */
  public long framesProcessed() {
    lock.lock();
    try {
      return frames;
    } finally {
      lock.unlock();
    }
  }

  /**
   * Waits until at least {@code count} frames have been tracked.
   *
   * @return false if the timeout passed first or the server stopped
   */
  public boolean awaitFrames(long count, long timeout, TimeUnit unit) throws InterruptedException {
    long deadline = clock.nanoTime() + unit.toNanos(timeout);
    lock.lock();
    try {
      while (frames < count) {
        if (stopped || !clock.awaitUntil(lock, changed, deadline)) {
          return frames >= count;
        }
      }
      return true;
    } finally {
      lock.unlock();
    }
  }

  /** Requests served ({@code '0'} bytes answered; counted as the answer is sent). */
  public long requestsServed() {
    return requests.get();
  }

  /** Bytes received that were neither {@code '0'} nor {@code '1'}. */
  public long garbageBytes() {
    return garbage.get();
  }

  /** Clients accepted so far. */
  public long clientsAccepted() {
    return accepted.get();
  }

  /** Clients refused because the server was full. */
  public long clientsRefused() {
    return refused.get();
  }

  /** Clients disconnected because they were idle past the idle timeout. */
  public long clientsDroppedIdle() {
    return droppedIdle.get();
  }

  /** Idle clients disconnected to make room for a newcomer in a full server. */
  public long clientsReplaced() {
    return replaced.get();
  }

  /** Clients connected now. */
  public int activeClients() {
    return clients.size();
  }

  /** Frames the source failed to deliver. */
  public long sourceErrors() {
    return sourceErrors.get();
  }

  // ---------------------------------------------------------------- stopping

  /** Asks the server to stop; {@link #awaitStopRequest} wakes. Does not wait. */
  public void requestStop() {
    lock.lock();
    try {
      stopRequested = true;
      changed.signalAll();
    } finally {
      lock.unlock();
    }
  }

  /**
   * Waits until {@link #requestStop()} is called (by a quitting client, say) or the server stops.
   */
  public void awaitStopRequest() throws InterruptedException {
    lock.lock();
    try {
      while (!stopRequested && !stopped) {
        changed.await();
      }
    } finally {
      lock.unlock();
    }
  }

  /**
   * Stops accepting, disconnects every client, stops the pipeline and joins all threads.
   * Idempotent. Does not close the image source (its creator does).
   */
  public void stop() {
    List<Thread> toJoin = new ArrayList<>();
    lock.lock();
    try {
      if (stopped) {
        return;
      }
      running = false;
      stopped = true;
      changed.signalAll();
      if (serverSocket != null) {
        try {
          serverSocket.close();
        } catch (IOException ignored) {
          // closing anyway
        }
      }
      for (Client c : clients) {
        closeQuietly(c.socket);
      }
      if (pipelineThread != null) {
        pipelineThread.interrupt();
        toJoin.add(pipelineThread);
      }
      if (acceptThread != null) {
        toJoin.add(acceptThread);
      }
      toJoin.addAll(clientThreads);
    } finally {
      lock.unlock();
    }
    boolean interrupted = false;
    for (Thread t : toJoin) {
      if (t == Thread.currentThread()) {
        continue;
      }
      try {
        t.join(JOIN_MS);
      } catch (InterruptedException e) {
        interrupted = true;
      }
      if (t.isAlive()) {
        LOG.warn("ACTS: thread {} did not stop within {} ms", t.getName(), JOIN_MS);
      }
    }
    if (interrupted) {
      Thread.currentThread().interrupt();
    }
    LOG.info("ACTS server on port {} stopped", port);
  }

  /** Same as {@link #stop()}. */
  @Override
  public void close() {
    stop();
  }
}
