package org.jaria.net.client;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.server.ArServerBase;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A client of an ArNetworking server (ARIA's {@code ArClientBase}): connects and logs in, learns
 * the server's data list, and then asks for data by name — once ({@link #requestOnce}), at an
 * interval ({@link #request}) — receiving the packets in handlers ({@link #addHandler}). It talks
 * to ARIA's C++ servers (serverDemo, ARNL's guiServer) as well as to JAria's {@code ArServerBase}.
 *
 * <pre>{@code
 * try (ArClientBase client = new ArClientBase("monitor")) {
 *   client.connect("localhost", 7272, "", "");
 *   client.addHandler("update", p -> System.out.println(RobotUpdate.read(p)));
 *   client.request("update", 100);
 *   client.requestOnce("ratioDrive", ArNetPacketArgs.of(50.0, 0.0, 100.0));
 * }
 * }</pre>
 *
 * <p>The client asks for TCP only (it sends ArNetworking's TCP_ONLY), which every ArNetworking
 * server honours. One reader thread ("jaria-net-client-NAME") receives packets and runs the
 * handlers; handlers must be quick. Sending is thread-safe.
 *
 * <p><b>Replies.</b> ArNetworking replies carry the request's command number but no request id: a
 * {@link #requestOnce} future completes with the next packet of that data, in order. Data whose
 * flags say it returns nothing (RETURN_NONE) complete at once with an empty packet. A JAria server
 * reports a failed request with its {@code requestFailed} packet, which fails the future.
 */
public final class ArClientBase implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArClientBase.class);

  private final ClientOptions options;
  private final Map<String, List<Consumer<ArNetPacket>>> handlers = new ConcurrentHashMap<>();
  private final Map<String, Long> requests = new ConcurrentHashMap<>();
  private final Map<String, byte[]> requestArgs = new ConcurrentHashMap<>();
  private final List<ConnectionListener> listeners = new CopyOnWriteArrayList<>();
  private final AtomicLong updates = new AtomicLong();
  private final AtomicLong handlerFailures = new AtomicLong();
  private final Object sendLock = new Object();

  // Guarded by "this".
  private final DataList dataList = new DataList();

  @GuardedBy("this")
  private final Map<Integer, Deque<CompletableFuture<ArNetPacket>>> waiting = new LinkedHashMap<>();

  @GuardedBy("this")
  private final Map<Integer, java.io.ByteArrayOutputStream> partial = new LinkedHashMap<>();

  /** Largest reply of several packets gathered for a {@link #requestOnce}. */
  private static final int MAX_GATHERED = 64 << 20;

  private volatile Socket socket;
  // The socket being connected: disconnect() closes it so that a server that never finishes the
  // login cannot keep the caller waiting.
  private volatile Socket connecting;
  private volatile OutputStream out;
  private volatile Thread reader;
  private volatile boolean connected;
  private volatile String lastError;
  private volatile String serverName = "";

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
   * Connects and logs in, waiting at most the connect timeout. Requests made at an interval before
   * are sent again once logged in.
   *
   * @param user user name ("" for a server that needs no login)
   * @param password the password ("" or null for none)
   * @throws ArClientException if the server cannot be reached, is not an ArNetworking server, or
   *     rejects the login: the message says which
   * @throws IllegalStateException if already connected
   */
  public synchronized void connect(String host, int port, String user, String password)
      throws ArClientException {
    if (connected) {
      throw new IllegalStateException("already connected; disconnect() first");
    }
    Thread old = reader;
    if (old != null) {
      joinQuietly(old);
    }
    dataList.clear();
    Socket s = new Socket();
    connecting = s;
    try {
      int timeout = (int) options.connectTimeout().toMillis();
      s.connect(new InetSocketAddress(host, port), timeout);
      s.setTcpNoDelay(true);
      // The whole login, not each read, must fit in the timeout: a server that trickles bytes
      // would otherwise hold the caller for ever.
      LoginDeadline deadline = new LoginDeadline(s, options.connectTimeout());
      DataInputStream in = new DataInputStream(new BufferedInputStream(deadline));
      OutputStream o = s.getOutputStream();
      ClientLogin.login(
          in,
          o,
          user == null ? "" : user,
          password == null ? "" : password,
          options.serverKey(),
          dataList);
      deadline.lift();
      socket = s;
      out = o;
      connected = true;
      serverName = "ArNetworking server at " + host + ":" + port;
      Thread t = new Thread(() -> readLoop(in), "jaria-net-client-" + options.name());
      t.setDaemon(true);
      reader = t;
      t.start();
    } catch (SocketTimeoutException e) {
      closeQuietly(s);
      throw fail(
          "no login answer from "
              + host
              + ":"
              + port
              + " within "
              + options.connectTimeout().toMillis()
              + " ms: is it an ArNetworking server?");
    } catch (IOException e) {
      closeQuietly(s);
      throw fail(
          "cannot connect to "
              + host
              + ":"
              + port
              + " ("
              + e.getMessage()
              + "): is the server running there?");
    } catch (ArClientException e) {
      closeQuietly(s);
      throw fail(e.getMessage());
    } catch (ArNetPacketException e) {
      closeQuietly(s);
      throw fail(host + ":" + port + " sent something that is not ArNetworking: " + e.getMessage());
    } finally {
      connecting = null;
    }
    for (Map.Entry<String, Long> r : requests.entrySet()) {
      if (dataList.contains(r.getKey())) {
        sendRequest(r.getKey(), r.getValue(), requestArgs.get(r.getKey()));
      }
    }
    log.info("connected to {} as '{}' ({} data)", serverName, user, dataList.size());
    for (ConnectionListener l : listeners) {
      l.connected(this);
    }
  }

  private ArClientException fail(String why) {
    lastError = why;
    return new ArClientException(why);
  }

  private void readLoop(DataInputStream in) {
    String why = "the connection was closed";
    try {
      while (connected) {
        ArNetPacket p = ClientLogin.readPacket(in);
        if (!dispatch(p)) {
          why = "the server shut the connection down";
          break;
        }
      }
    } catch (EOFException e) {
      why = "the server closed the connection";
    } catch (IOException e) {
      why = connected ? "connection lost: " + e.getMessage() : "disconnected";
    } catch (ArNetPacketException e) {
      why = "the server sent a broken packet: " + e.getMessage();
    }
    lost(why);
  }

  /** Handles one packet; false if the server shut down. */
  private boolean dispatch(ArNetPacket p) {
    int cmd = p.getCommand();
    if (cmd == Protocol.SERVER_SHUTDOWN) {
      return false;
    }
    if (cmd < Protocol.FIRST_DATA_COMMAND) {
      if (cmd >= Protocol.SERVER_LIST && cmd <= Protocol.SERVER_LIST_GROUP_AND_FLAGS_SINGLE) {
        dataList.add(p);
      }
      return true;
    }
    DataInfo d;
    CompletableFuture<ArNetPacket> f = null;
    ArNetPacket gathered = null;
    synchronized (this) {
      d = dataList.get(cmd);
      if (d != null && d.name().equals("requestFailed")) {
        failRequest(p);
        return true;
      }
      Deque<CompletableFuture<ArNetPacket>> q = waiting.get(cmd);
      if (q != null && !q.isEmpty()) {
        if (d != null && d.hasDataFlag("RETURN_UNTIL_EMPTY")) {
          // A reply of several packets, ended by an empty one: gathered into one reader.
          java.io.ByteArrayOutputStream b =
              partial.computeIfAbsent(cmd, k -> new java.io.ByteArrayOutputStream());
          if (p.getDataLength() > 0) {
            if (b.size() + p.getDataLength() > MAX_GATHERED) {
              partial.remove(cmd);
              q.poll()
                  .completeExceptionally(
                      new ArClientException("the reply of " + d.name() + " is over 64 MiB"));
            } else {
              b.writeBytes(p.toByteArray());
            }
          } else {
            partial.remove(cmd);
            byte[] all = b.toByteArray();
            f = q.poll();
            gathered = ArNetPacket.wrap(cmd, all, 0, all.length);
          }
        } else {
          f = q.poll();
        }
      }
    }
    updates.incrementAndGet();
    if (f != null) {
      f.complete(gathered != null ? gathered : p.toReader());
    }
    if (d != null) {
      for (Consumer<ArNetPacket> h : handlers.getOrDefault(d.name(), List.of())) {
        try {
          h.accept(p.toReader());
        } catch (RuntimeException e) {
          handlerFailures.incrementAndGet();
          log.warn("a handler of {} failed", d.name(), e);
        }
      }
    }
    return true;
  }

  private synchronized void forget(int id, CompletableFuture<ArNetPacket> f) {
    Deque<CompletableFuture<ArNetPacket>> q = waiting.get(id);
    if (q != null) {
      // By identity: a future has no equals of its own.
      q.removeIf(x -> x == f);
    }
  }

  @GuardedBy("this") // dispatch calls it holding the lock
  private void failRequest(ArNetPacket p) {
    String name = p.bufToStr();
    String why = p.bufToStr();
    NetError code = p.hasMore() ? NetError.fromCode(p.bufToByte2()) : null;
    DataInfo d = dataList.get(name);
    if (d != null) {
      Deque<CompletableFuture<ArNetPacket>> q = waiting.get(d.id());
      CompletableFuture<ArNetPacket> f = q == null ? null : q.poll();
      if (f != null) {
        f.completeExceptionally(new ArClientException(code, why));
        return;
      }
    }
    log.info("the server says a request failed: {}", why);
  }

  private void lost(String why) {
    boolean was;
    List<CompletableFuture<ArNetPacket>> pending = new ArrayList<>();
    synchronized (this) {
      was = connected;
      if (was) {
        // Said before the connection reads as lost: whoever sees isConnected() turn false
        // finds the reason (it was set after, and a test once read null in between).
        lastError = why;
      }
      connected = false;
      for (Deque<CompletableFuture<ArNetPacket>> q : waiting.values()) {
        pending.addAll(q);
      }
      waiting.clear();
      partial.clear();
    }
    closeQuietly(socket);
    for (CompletableFuture<ArNetPacket> f : pending) {
      f.completeExceptionally(new ArClientException("disconnected: " + why));
    }
    if (was) {
      log.info("disconnected from {}: {}", serverName, why);
      for (ConnectionListener l : listeners) {
        l.disconnected(this, why);
      }
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
    return connected;
  }

  /** Why the last connect failed or the connection was lost (null if it never was). */
  public String getLastError() {
    return lastError;
  }

  /** The server, for people ("ArNetworking server at host:port"). */
  public String getServerName() {
    return serverName;
  }

  /** Says goodbye (ArNetworking's SHUTDOWN) and closes the connection; safe to call again. */
  public void disconnect() {
    closeQuietly(connecting);
    if (connected) {
      try {
        send(new ArNetPacket(Protocol.CLIENT_SHUTDOWN));
      } catch (ArClientException e) {
        // Closing anyway.
      }
    }
    lost("disconnected");
    Thread t = reader;
    if (t != null && t != Thread.currentThread()) {
      joinQuietly(t);
    }
  }

  /** Disconnects. */
  @Override
  public void close() {
    disconnect();
  }

  private static void joinQuietly(Thread t) {
    try {
      t.join(TimeUnit.SECONDS.toMillis(5));
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  private static void closeQuietly(Socket s) {
    if (s != null) {
      try {
        s.close();
      } catch (IOException e) {
        // Nothing more to do.
      }
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

  /** The server's data list (what this user may use), in command order. */
  public synchronized List<DataInfo> getDataList() {
    return dataList.list();
  }

  /** Whether the server offers data {@code name} (ArNetworking's {@code dataExists}). */
  public synchronized boolean dataExists(String name) {
    return dataList.contains(name);
  }

  /** The command number of {@code name}, or 0 (ArNetworking's {@code findCommandFromName}). */
  public synchronized int findCommandFromName(String name) {
    DataInfo d = dataList.get(name);
    return d == null ? 0 : d.id();
  }

  private synchronized DataInfo need(String name) throws ArClientException {
    if (!connected) {
      throw new ArClientException("not connected; connect() first");
    }
    DataInfo d = dataList.get(name);
    if (d == null) {
      throw new ArClientException("the server has no data '" + name + "'");
    }
    return d;
  }

  private void send(ArNetPacket p) throws ArClientException {
    OutputStream o = out;
    if (o == null || !connected) {
      throw new ArClientException("not connected; connect() first");
    }
    synchronized (sendLock) {
      try {
        o.write(p.toWire());
        o.flush();
      } catch (IOException e) {
        throw new ArClientException("sending failed: " + e.getMessage());
      }
    }
  }

  /**
   * Asks for data {@code name} once, with {@code args} (null for none), as ArNetworking's {@code
   * requestOnce}. The future completes with the reply (an empty packet at once for data that
   * returns nothing), or fails with an {@link ArClientException} if the data does not exist, the
   * server reports a failure, the request times out or the connection is lost.
   */
  public CompletableFuture<ArNetPacket> requestOnce(String name, ArNetPacket args) {
    CompletableFuture<ArNetPacket> f = new CompletableFuture<>();
    try {
      DataInfo d = need(name);
      ArNetPacket p = args == null ? new ArNetPacket() : args.toReader();
      ArNetPacket send = new ArNetPacket(d.id());
      byte[] body = p.toByteArray();
      send.dataToBuf(body);
      // A JAria server (it lists requestFailed) acknowledges commands that return nothing.
      boolean none = d.returnsNothing() && !dataExists(ArServerBase.REQUEST_FAILED);
      if (!none) {
        synchronized (this) {
          waiting.computeIfAbsent(d.id(), k -> new ArrayDeque<>()).add(f);
        }
      }
      send(send);
      if (none) {
        f.complete(new ArNetPacket(d.id()).toReader());
      } else {
        int id = d.id();
        // A request the server never answers must not stay queued for ever (a client that asks
        // again and again, as a video forwarder does, would grow the queue without bound).
        var unused =
            f.orTimeout(options.requestTimeout().toMillis(), TimeUnit.MILLISECONDS)
                .whenComplete((r, e) -> forget(id, f));
      }
    } catch (ArClientException | ArNetPacketException e) {
      f.completeExceptionally(e);
    }
    return f;
  }

  /**
   * As {@link #requestOnce(String, ArNetPacket)} with arguments written by type: a Double or Float
   * as a double, an Integer as a byte4, a Short as a byte2, a Byte as a byte, a Long as a byte8, a
   * Boolean as a ubyte 1/0, a String as a string, a byte[] as raw bytes.
   */
  public CompletableFuture<ArNetPacket> requestOnce(String name, Object... args) {
    try {
      return requestOnce(name, ArNetPacketArgs.of(args));
    } catch (IllegalArgumentException e) {
      return CompletableFuture.failedFuture(e);
    }
  }

  /**
   * Asks for data {@code name} every {@code intervalMs} milliseconds (-1: whenever it changes or is
   * broadcast), as ArNetworking's {@code request}; the packets go to the handlers. Remembered and
   * sent again after a reconnect. ArNetworking does not acknowledge a request: the future completes
   * as soon as it is sent.
   */
  public CompletableFuture<Duration> request(String name, long intervalMs) {
    return request(name, intervalMs, null);
  }

  /**
   * As {@link #request(String, long)} with arguments (for example the sensor name of
   * getSensorCurrent). A new request of the same data replaces the old one, as in ArNetworking.
   */
  public CompletableFuture<Duration> request(String name, long intervalMs, ArNetPacket args) {
    requests.put(name, intervalMs);
    if (args == null) {
      requestArgs.remove(name);
    } else {
      requestArgs.put(name, args.toByteArray());
    }
    try {
      sendRequest(name, intervalMs, args == null ? null : args.toByteArray());
      return CompletableFuture.completedFuture(Duration.ofMillis(intervalMs));
    } catch (ArClientException e) {
      return CompletableFuture.failedFuture(e);
    }
  }

  private void sendRequest(String name, long intervalMs, byte[] args) throws ArClientException {
    DataInfo d = need(name);
    ArNetPacket p = new ArNetPacket(Protocol.CLIENT_REQUEST);
    p.uByte2ToBuf(d.id()).byte4ToBuf((int) Math.max(-1, Math.min(Integer.MAX_VALUE, intervalMs)));
    if (args != null) {
      p.dataToBuf(args);
    }
    send(p);
  }

  /** Stops a request made with {@link #request} (ArNetworking's {@code requestStop}). */
  public void requestStop(String name) {
    requests.remove(name);
    requestArgs.remove(name);
    try {
      DataInfo d = need(name);
      ArNetPacket p = new ArNetPacket(Protocol.CLIENT_REQUEST_STOP);
      p.uByte2ToBuf(d.id());
      send(p);
    } catch (ArClientException e) {
      log.debug("requestStop {}: {}", name, e.getMessage());
    }
  }

  /** The requests made at an interval: name → interval in ms. */
  public Map<String, Long> getSubscriptions() {
    return Collections.unmodifiableMap(new LinkedHashMap<>(requests));
  }

  /** Adds a handler for the packets of data {@code name} (ArNetworking's {@code addHandler}). */
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

  /** Handlers that threw. */
  public long getHandlerFailures() {
    return handlerFailures.get();
  }

  /** Data packets received. */
  public long getUpdatesReceived() {
    return updates.get();
  }

  /** The options. */
  public ClientOptions getOptions() {
    return options;
  }
}
