package org.jaria.net.client;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A client of a robot's {@link org.jaria.net.server.ArServerBase} (ArNetworking's {@code
 * ArClientBase}): connect and log in, ask for data once, subscribe to published data at a rate with
 * a handler, send commands, disconnect.
 *
 * <pre>{@code
 * try (ArClientBase client = new ArClientBase("monitor")) {
 *   client.connect("robot.local", 7272, "operator", "secret");
 *   client.addHandler("update", p -> System.out.println(RobotUpdate.read(p)));
 *   client.request("update", 100);                        // 10 Hz
 *   client.requestOnce("gotoPose", 2000.0, 0.0, 0.0).get(); // a command
 * }
 * }</pre>
 *
 * <p><b>Threads.</b> Every method may be called from any thread and none blocks on the network
 * except {@link #connect} (requests are queued to a writer thread and return futures). Handlers and
 * listeners run on the client's reader thread, one at a time, in arrival order; a JavaFX program
 * hands their work to the application thread with {@code Platform.runLater}, and keeps them short.
 *
 * <p><b>Reconnecting.</b> After a disconnect (asked for, or a lost connection) the same client can
 * {@link #connect} again: handlers, listeners and subscriptions are kept, and subscriptions are
 * sent again once logged in.
 */
public final class ArClientBase implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArClientBase.class);

  private final ClientOptions options;
  private final Map<String, List<Consumer<ArNetPacket>>> handlers = new ConcurrentHashMap<>();
  private final Map<String, Long> subscriptions = new ConcurrentHashMap<>();
  private final Map<String, CompletableFuture<Duration>> subscribeWaiters =
      new ConcurrentHashMap<>();
  private final List<ConnectionListener> listeners = new CopyOnWriteArrayList<>();
  private final AtomicInteger nextReqId = new AtomicInteger();
  private final AtomicLong updates = new AtomicLong();
  private final AtomicLong handlerFailures = new AtomicLong();
  private final ClientConnection.Events events = new Events();
  private volatile ClientConnection conn;
  private volatile String lastError;

  /** A client with the default options. */
  public ArClientBase(String name) {
    this(ClientOptions.defaults(name));
  }

  /** A client with {@code options}. */
  public ArClientBase(ClientOptions options) {
    this.options = options;
  }

  // ------------------------------------------------------------------ connecting

  /**
   * Connects and logs in, waiting at most the connect timeout. Subscriptions made earlier are sent
   * once logged in.
   *
   * @param user user name ("" for a server that needs no login)
   * @param password the password ("" or null for none)
   * @throws ArClientException if the server cannot be reached or refuses the login: the message
   *     says which (for example "login refused: wrong user name or password")
   * @throws IllegalStateException if already connected
   */
  public void connect(String host, int port, String user, String password)
      throws ArClientException {
    ClientConnection c;
    synchronized (this) {
      ClientConnection old = conn;
      if (old != null && !old.isClosed()) {
        throw new IllegalStateException("already connected; disconnect() first");
      }
      if (old != null) {
        joinQuietly(old);
      }
      try {
        c = ClientConnection.open(options, events, host, port, user, password);
      } catch (ArClientException e) {
        lastError = e.getMessage();
        throw e;
      }
      conn = c;
      c.start("jaria-net-client-" + options.name() + "-" + c.clientId);
      for (Map.Entry<String, Long> s : subscriptions.entrySet()) {
        sendSubscribe(c, s.getKey(), s.getValue());
      }
    }
    log.info("connected to {} at {}:{} as '{}'", c.serverName, host, port, user);
    for (ConnectionListener l : listeners) {
      l.connected(this);
    }
  }

  /**
   * ARIA's form of {@link #connect}: returns false instead of throwing; {@link #getLastError()}
   * says why.
   */
  public boolean blockingConnect(String host, int port, String user, String password) {
    try {
      connect(host, port, user, password);
      return true;
    } catch (ArClientException e) {
      return false;
    }
  }

  /** Whether connected and logged in. */
  public boolean isConnected() {
    ClientConnection c = conn;
    return c != null && !c.isClosed();
  }

  /** Why the last connection attempt failed or the last connection ended, or null. */
  public String getLastError() {
    return lastError;
  }

  /** The server's name, or null before the first connection. */
  public String getServerName() {
    ClientConnection c = conn;
    return c == null ? null : c.serverName;
  }

  /**
   * Says goodbye to the server and closes the connection, waiting for the client's threads to end.
   * Handlers and subscriptions are kept for a later {@link #connect}.
   */
  public void disconnect() {
    ClientConnection c = conn;
    if (c != null) {
      c.closeGracefully("disconnected by the client");
      joinQuietly(c);
    }
  }

  /** {@link #disconnect()}. */
  @Override
  public void close() {
    disconnect();
  }

  private static void joinQuietly(ClientConnection c) {
    try {
      c.join();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** Adds a listener for connecting and disconnecting. */
  public void addConnectionListener(ConnectionListener l) {
    listeners.add(l);
  }

  /** Removes a listener. */
  public void removeConnectionListener(ConnectionListener l) {
    listeners.remove(l);
  }

  // ------------------------------------------------------------------ data

  /** The data the server offers this user (empty when not connected). */
  public List<DataInfo> getDataList() {
    ClientConnection c = conn;
    return c == null ? List.of() : List.copyOf(c.byName.values());
  }

  /** Whether the server offers data of this name (ArNetworking's {@code dataExists}). */
  public boolean dataExists(String name) {
    ClientConnection c = conn;
    return c != null && c.byName.containsKey(name);
  }

  /**
   * Asks for data once, or sends a command: the future completes with the reply (an empty packet
   * for a command), or exceptionally with an {@link ArClientException}: a server error (with its
   * {@link ArClientException#getCode() code}), a lost connection, or no reply within the request
   * timeout.
   */
  public CompletableFuture<ArNetPacket> requestOnce(String name, ArNetPacket args) {
    ClientConnection c = conn;
    if (c == null || c.isClosed()) {
      return CompletableFuture.failedFuture(notConnected());
    }
    DataInfo d = c.byName.get(name);
    if (d == null) {
      return CompletableFuture.failedFuture(
          new ArClientException(
              NetError.UNKNOWN_DATA,
              "the server offers no '" + name + "' (or this user may not use it)"));
    }
    int reqId = nextReqId.incrementAndGet();
    ArNetPacket body = new ArNetPacket().intToBuf(reqId).intToBuf(d.id());
    if (args != null) {
      body.encodedToBuf(args.toByteArray());
    }
    return c.call(reqId, name, Frames.frame(Kind.CALL, body));
  }

  /** {@link #requestOnce(String, ArNetPacket)} with simple arguments ({@link ArNetPacket#of}). */
  public CompletableFuture<ArNetPacket> requestOnce(String name, Object... args) {
    return requestOnce(name, ArNetPacket.of(args));
  }

  /**
   * Subscribes to published data: the server sends it every {@code intervalMs} (or at its minimum
   * interval, if shorter) whenever it has changed, to the handlers added with {@link #addHandler}.
   * The subscription is kept over reconnections. The future completes with the interval the server
   * granted.
   */
  public CompletableFuture<Duration> request(String name, long intervalMs) {
    subscriptions.put(name, intervalMs);
    CompletableFuture<Duration> f = new CompletableFuture<>();
    CompletableFuture<Duration> old = subscribeWaiters.put(name, f);
    if (old != null) {
      // Someone still waits for an earlier request of the same subscription: answer both.
      CompletableFuture<Duration> unused = f.whenComplete((r, e) -> complete(old, r, e));
    }
    ClientConnection c = conn;
    if (c != null && !c.isClosed()) {
      sendSubscribe(c, name, intervalMs);
    }
    return f;
  }

  private static void complete(CompletableFuture<Duration> f, Duration r, Throwable e) {
    if (e != null) {
      f.completeExceptionally(e);
    } else {
      f.complete(r);
    }
  }

  private void sendSubscribe(ClientConnection c, String name, long intervalMs) {
    DataInfo d = c.byName.get(name);
    CompletableFuture<Duration> waiter = subscribeWaiters.get(name);
    if (d == null) {
      if (waiter != null && subscribeWaiters.remove(name, waiter)) {
        waiter.completeExceptionally(
            new ArClientException(NetError.UNKNOWN_DATA, "the server offers no '" + name + "'"));
      }
      return;
    }
    int reqId = nextReqId.incrementAndGet();
    CompletableFuture<Long> unused =
        c.subscribe(reqId, Frames.frame(Kind.SUBSCRIBE, reqId, d.id(), intervalMs))
            .whenComplete(
                (granted, e) -> {
                  CompletableFuture<Duration> w = subscribeWaiters.get(name);
                  if (w != null && subscribeWaiters.remove(name, w)) {
                    complete(w, granted == null ? null : Duration.ofMillis(granted), e);
                  }
                });
  }

  /** Stops a subscription (ArNetworking's {@code requestStop}). */
  public void requestStop(String name) {
    subscriptions.remove(name);
    ClientConnection c = conn;
    if (c != null && !c.isClosed()) {
      DataInfo d = c.byName.get(name);
      if (d != null) {
        c.send(Frames.frame(Kind.UNSUBSCRIBE, d.id()));
      }
    }
  }

  /** The current subscriptions: name → interval asked for, ms. */
  public Map<String, Long> getSubscriptions() {
    return Map.copyOf(subscriptions);
  }

  /**
   * Adds a handler for updates of {@code name} (ArNetworking's {@code addHandler}). Each handler
   * gets its own packet to read, on the reader thread.
   */
  public void addHandler(String name, Consumer<ArNetPacket> handler) {
    handlers.computeIfAbsent(name, k -> new CopyOnWriteArrayList<>()).add(handler);
  }

  /** Removes a handler. */
  public void remHandler(String name, Consumer<ArNetPacket> handler) {
    List<Consumer<ArNetPacket>> l = handlers.get(name);
    if (l != null) {
      l.remove(handler);
    }
  }

  /** Measures the round trip to the server; completes with it. */
  public CompletableFuture<Duration> ping() {
    ClientConnection c = conn;
    if (c == null || c.isClosed()) {
      return CompletableFuture.failedFuture(notConnected());
    }
    return c.ping()
        .thenApply(Duration::ofNanos)
        .orTimeout(options.requestTimeout().toMillis(), TimeUnit.MILLISECONDS);
  }

  /** Handler calls that threw (they are logged and skipped). */
  public long getHandlerFailures() {
    return handlerFailures.get();
  }

  /** Updates received so far (over all connections). */
  public long getUpdatesReceived() {
    return updates.get();
  }

  /** The options. */
  public ClientOptions getOptions() {
    return options;
  }

  private ArClientException notConnected() {
    return new ArClientException(
        null, "not connected" + (lastError == null ? "" : " (" + lastError + ")"));
  }

  private final class Events implements ClientConnection.Events {
    @Override
    public void update(ClientConnection c, int dataId, long version, byte[] payload) {
      updates.incrementAndGet();
      DataInfo d = c.byId.get(dataId);
      if (d == null) {
        return;
      }
      List<Consumer<ArNetPacket>> l = handlers.get(d.name());
      if (l == null) {
        return;
      }
      for (Consumer<ArNetPacket> h : l) {
        try {
          h.accept(ArNetPacket.wrap(payload));
        } catch (RuntimeException e) {
          // A bad handler (or an update it cannot decode) must not end the connection.
          if (handlerFailures.incrementAndGet() % 100 == 1) {
            log.warn("a handler for {} failed (#{})", d.name(), handlerFailures.get(), e);
          }
        }
      }
    }

    @Override
    public void closed(ClientConnection c, String reason) {
      lastError = reason;
      log.info("disconnected from {}: {}", c.serverName, reason);
      List<ConnectionListener> ls = new ArrayList<>(listeners);
      for (ConnectionListener l : ls) {
        try {
          l.disconnected(ArClientBase.this, reason);
        } catch (RuntimeException e) {
          log.warn("a connection listener failed", e);
        }
      }
    }
  }
}
