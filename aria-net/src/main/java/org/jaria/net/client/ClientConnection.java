package org.jaria.net.client;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Frames;
import org.jaria.net.protocol.Kind;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.PasswordHash;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One TCP connection of an {@link ArClientBase}, from login to close: a reader thread that splits
 * frames and completes requests, and a writer thread that drains a bounded queue (so a caller — a
 * JavaFX event handler — never blocks on a slow network) and pings when idle.
 */
final class ClientConnection {

  private static final Logger log = LoggerFactory.getLogger(ClientConnection.class);

  private static final byte[] POISON = new byte[0];

  /** What the connection tells its client. */
  interface Events {
    /** A complete update of data {@code dataId} (reader thread). */
    void update(ClientConnection c, int dataId, long version, byte[] payload);

    /** The connection ended (once). */
    void closed(ClientConnection c, String reason);
  }

  private static final class PendingCall {
    final CompletableFuture<ArNetPacket> future = new CompletableFuture<>();
    final String name;
    ByteArrayOutputStream parts;

    PendingCall(String name) {
      this.name = name;
    }
  }

  private final ClientOptions options;
  private final Events events;
  private final Socket socket;
  private final DataInputStream in;
  private final OutputStream out;
  private final LinkedBlockingQueue<byte[]> sendQueue;
  private final Map<Integer, PendingCall> calls = new ConcurrentHashMap<>();
  private final Map<Integer, CompletableFuture<Long>> subscribes = new ConcurrentHashMap<>();
  private final Map<Long, CompletableFuture<Long>> pings = new ConcurrentHashMap<>();
  private final Map<Integer, ByteArrayOutputStream> partialUpdates = new HashMap<>();
  private final AtomicBoolean closed = new AtomicBoolean();
  private volatile String closeReason;
  private Thread reader;
  private Thread writer;

  final Map<String, DataInfo> byName;
  final Map<Integer, DataInfo> byId;
  final String serverName;
  final int clientId;
  final long minIntervalMs;

  private ClientConnection(
      ClientOptions options,
      Events events,
      Socket socket,
      DataInputStream in,
      OutputStream out,
      String serverName,
      int clientId,
      long minIntervalMs,
      List<DataInfo> data) {
    this.options = options;
    this.events = events;
    this.socket = socket;
    this.in = in;
    this.out = out;
    this.serverName = serverName;
    this.clientId = clientId;
    this.minIntervalMs = minIntervalMs;
    this.sendQueue = new LinkedBlockingQueue<>(options.sendQueue());
    Map<String, DataInfo> n = new LinkedHashMap<>();
    Map<Integer, DataInfo> i = new HashMap<>();
    for (DataInfo d : data) {
      n.put(d.name(), d);
      i.put(d.id(), d);
    }
    this.byName = Collections.unmodifiableMap(n);
    this.byId = Map.copyOf(i);
  }

  /**
   * Connects and logs in (on the calling thread).
   *
   * @throws ArClientException if the server cannot be reached, refuses the login or breaks the
   *     protocol; the message says which
   */
  static ClientConnection open(
      ClientOptions o, Events events, String host, int port, String user, String password)
      throws ArClientException {
    Socket s = new Socket();
    try {
      int timeout = (int) o.connectTimeout().toMillis();
      s.connect(new InetSocketAddress(host, port), timeout);
      s.setTcpNoDelay(true);
      s.setSoTimeout(timeout);
      DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream(), 65536));
      OutputStream out = new BufferedOutputStream(s.getOutputStream(), 65536);
      out.write(
          Frames.frame(
              Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, o.name(), user == null ? "" : user));
      out.flush();
      ArNetPacket ch = expect(readFrame(in, o.maxFrame()), Kind.CHALLENGE);
      if (!Protocol.MAGIC.equals(ch.bufToStr())) {
        throw new ArClientException(NetError.MALFORMED, "the server is not a JAria server");
      }
      ch.bufToLong();
      String serverName = ch.bufToStr();
      byte[] nonce = ch.bufToData();
      byte[] salt = ch.bufToData();
      int iterations = ch.bufToInt();
      byte[] proof = new byte[0];
      if (iterations > 0) {
        if (iterations > PasswordHash.MAX_ITERATIONS) {
          throw new ArClientException(
              NetError.MALFORMED, "the server asks for " + iterations + " PBKDF2 rounds: too many");
        }
        byte[] key = PasswordHash.derive(password == null ? "" : password, salt, iterations);
        proof = PasswordHash.proof(key, nonce);
      }
      out.write(Frames.frame(Kind.LOGIN, (Object) proof));
      out.flush();
      ArNetPacket w = expect(readFrame(in, o.maxFrame()), Kind.WELCOME);
      int clientId = w.bufToInt();
      long minInterval = w.bufToLong();
      w.bufToLong();
      int n = w.bufToArray();
      List<DataInfo> data = new ArrayList<>(n);
      for (int i = 0; i < n; i++) {
        data.add(DataInfo.read(w));
      }
      s.setSoTimeout((int) o.readTimeout().toMillis());
      return new ClientConnection(o, events, s, in, out, serverName, clientId, minInterval, data);
    } catch (IOException e) {
      closeQuietly(s);
      throw new ArClientException(
          "cannot connect to " + host + ":" + port + ": " + e.getMessage(), e);
    } catch (ProtocolException | ArNetPacketException e) {
      closeQuietly(s);
      throw new ArClientException(NetError.MALFORMED, "bad login reply: " + e.getMessage());
    } catch (ArClientException e) {
      closeQuietly(s);
      throw e;
    }
  }

  private static ArNetPacket expect(ArNetPacket p, Kind wanted) throws ArClientException {
    Kind k = Kind.fromCode(p.bufToLong());
    if (k == Kind.REFUSED || k == Kind.CLOSING) {
      NetError code = NetError.fromCode(p.bufToLong());
      throw new ArClientException(code, p.bufToStr());
    }
    if (k != wanted) {
      throw new ArClientException(
          NetError.PROTOCOL, "the server sent " + k + " where " + wanted + " was expected");
    }
    return p;
  }

  private static ArNetPacket readFrame(DataInputStream in, int maxFrame)
      throws IOException, ProtocolException {
    int len = in.readInt();
    Frames.checkLength(len, maxFrame);
    byte[] b = new byte[len];
    in.readFully(b);
    return ArNetPacket.wrap(b);
  }

  /** Starts the reader and writer threads. */
  void start(String threadPrefix) {
    reader = new Thread(this::readLoop, threadPrefix + "-read");
    writer = new Thread(this::writeLoop, threadPrefix + "-write");
    reader.setDaemon(true);
    writer.setDaemon(true);
    reader.start();
    writer.start();
  }

  boolean isClosed() {
    return closed.get();
  }

  String closeReason() {
    return closeReason;
  }

  /** Queues a frame; false if the connection is closed or the queue is full. */
  boolean send(byte[] frame) {
    return !closed.get() && sendQueue.offer(frame);
  }

  CompletableFuture<ArNetPacket> call(int reqId, String name, byte[] frame) {
    PendingCall p = new PendingCall(name);
    calls.put(reqId, p);
    // Forget the request however it ends (reply, error, timeout, disconnect).
    CompletableFuture<ArNetPacket> unused = p.future.whenComplete((r, e) -> calls.remove(reqId));
    if (!send(frame)) {
      p.future.completeExceptionally(notSent());
    } else {
      long ms = options.requestTimeout().toMillis();
      CompletableFuture.delayedExecutor(ms, TimeUnit.MILLISECONDS)
          .execute(
              () ->
                  p.future.completeExceptionally(
                      new ArClientException(
                          null, "no reply to '" + p.name + "' within " + ms + " ms")));
    }
    return p.future;
  }

  CompletableFuture<Long> subscribe(int reqId, byte[] frame) {
    CompletableFuture<Long> f = new CompletableFuture<>();
    subscribes.put(reqId, f);
    CompletableFuture<Long> unused = f.whenComplete((r, e) -> subscribes.remove(reqId));
    if (!send(frame)) {
      f.completeExceptionally(notSent());
    }
    return f;
  }

  CompletableFuture<Long> ping() {
    long token = System.nanoTime();
    CompletableFuture<Long> f = new CompletableFuture<>();
    pings.put(token, f);
    CompletableFuture<Long> unused = f.whenComplete((r, e) -> pings.remove(token));
    if (!send(Frames.frame(Kind.PING, token))) {
      f.completeExceptionally(notSent());
    }
    return f;
  }

  private ArClientException notSent() {
    return closed.get()
        ? new ArClientException(null, "not connected: " + closeReason)
        : new ArClientException(
            NetError.BUSY, options.sendQueue() + " frames already wait to be sent: slow down");
  }

  private void readLoop() {
    String reason = "connection lost";
    try {
      while (!closed.get()) {
        handle(readFrame(in, options.maxFrame()));
      }
    } catch (SocketTimeoutException e) {
      reason = "nothing from the server for " + options.readTimeout();
    } catch (EOFException e) {
      reason = closeReason != null ? closeReason : "the server closed the connection";
    } catch (IOException e) {
      reason = closeReason != null ? closeReason : "connection lost: " + e.getMessage();
    } catch (ProtocolException | ArNetPacketException e) {
      reason = "the server broke the protocol: " + e.getMessage();
    } catch (RuntimeException e) {
      log.warn("a handler failed on the client's reader thread; disconnecting", e);
      reason = "a handler failed: " + e;
    }
    close(reason);
  }

  private void handle(ArNetPacket p) throws ProtocolException {
    Kind k = Kind.fromCode(p.bufToLong());
    if (k == null) {
      throw new ProtocolException(NetError.MALFORMED, "unknown frame kind");
    }
    switch (k) {
      case RESPONSE -> {
        int reqId = p.bufToInt();
        p.bufToInt();
        boolean last = p.bufToBool();
        PendingCall c = calls.get(reqId);
        if (c != null) {
          c.parts = append(c.parts, p);
          if (last) {
            byte[] b = c.parts.toByteArray();
            c.parts = null;
            c.future.complete(ArNetPacket.wrap(b));
          }
        }
      }
      case UPDATE -> {
        int dataId = p.bufToInt();
        long version = p.bufToLong();
        boolean last = p.bufToBool();
        ByteArrayOutputStream b = append(partialUpdates.get(dataId), p);
        if (last) {
          partialUpdates.remove(dataId);
          events.update(this, dataId, version, b.toByteArray());
        } else {
          partialUpdates.put(dataId, b);
        }
      }
      case ERROR -> {
        int reqId = p.bufToInt();
        int dataId = p.bufToInt();
        NetError code = NetError.fromCode(p.bufToLong());
        String msg = p.bufToStr();
        ArClientException ex = new ArClientException(code, msg);
        PendingCall c = calls.get(reqId);
        CompletableFuture<Long> s = subscribes.get(reqId);
        if (c != null) {
          c.future.completeExceptionally(ex);
        } else if (s != null) {
          s.completeExceptionally(ex);
        } else {
          DataInfo d = byId.get(dataId);
          log.warn("server error for {}: {}", d == null ? dataId : d.name(), msg);
        }
      }
      case SUBSCRIBED -> {
        int reqId = p.bufToInt();
        p.bufToInt();
        long granted = p.bufToLong();
        CompletableFuture<Long> s = subscribes.get(reqId);
        if (s != null) {
          s.complete(granted);
        }
      }
      case PONG -> {
        long token = p.bufToLong();
        CompletableFuture<Long> f = pings.get(token);
        if (f != null) {
          f.complete(System.nanoTime() - token);
        }
      }
      case CLOSING -> {
        p.bufToLong();
        closeReason = "closed by the server: " + p.bufToStr();
      }
      default ->
          throw new ProtocolException(NetError.PROTOCOL, "the server sent " + k + " unexpectedly");
    }
  }

  private ByteArrayOutputStream append(ByteArrayOutputStream b, ArNetPacket p)
      throws ProtocolException {
    byte[] frame = p.toByteArray();
    int start = p.getReadLength();
    ByteArrayOutputStream out = b != null ? b : new ByteArrayOutputStream(frame.length - start);
    if (out.size() + frame.length - start > options.maxPayload()) {
      throw new ProtocolException(
          NetError.MALFORMED, "a reply of more than " + options.maxPayload() + " bytes");
    }
    out.write(frame, start, frame.length - start);
    return out;
  }

  private void writeLoop() {
    long pingNanos = options.pingInterval().toNanos();
    try {
      while (!closed.get()) {
        byte[] f = sendQueue.poll(pingNanos, TimeUnit.NANOSECONDS);
        if (f == POISON) {
          out.flush();
          break;
        }
        out.write(f != null ? f : Frames.frame(Kind.PING, System.nanoTime()));
        if (sendQueue.isEmpty()) {
          out.flush();
        }
      }
    } catch (IOException e) {
      close("connection lost while sending: " + e.getMessage());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /** Closes the connection (idempotent), failing every pending request with {@code reason}. */
  void close(String reason) {
    if (!closed.compareAndSet(false, true)) {
      return;
    }
    if (closeReason == null) {
      closeReason = reason;
    }
    sendQueue.clear();
    sendQueue.offer(POISON);
    closeQuietly(socket);
    ArClientException ex = new ArClientException(null, "disconnected: " + closeReason);
    for (PendingCall c : List.copyOf(calls.values())) {
      c.future.completeExceptionally(ex);
    }
    for (CompletableFuture<Long> f : List.copyOf(subscribes.values())) {
      f.completeExceptionally(ex);
    }
    for (CompletableFuture<Long> f : List.copyOf(pings.values())) {
      f.completeExceptionally(ex);
    }
    events.closed(this, closeReason);
  }

  /** Says goodbye (after what is already queued), waits briefly for it to go out, then closes. */
  void closeGracefully(String reason) {
    if (!closed.get()) {
      // Say why before saying goodbye: the server may close its end (and the reader see the end of
      // the stream) before this thread gets to close(); the user must still read our reason.
      if (closeReason == null) {
        closeReason = reason;
      }
      sendQueue.offer(Frames.frame(Kind.BYE));
      sendQueue.offer(POISON);
      Thread w = writer;
      if (w != null && w != Thread.currentThread()) {
        try {
          w.join(1000);
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
        }
      }
    }
    close(reason);
  }

  /** Waits for both threads to end (not from one of them). */
  void join() throws InterruptedException {
    Thread me = Thread.currentThread();
    for (Thread t : new Thread[] {reader, writer}) {
      if (t != null && t != me) {
        t.join(TimeUnit.SECONDS.toMillis(5));
        if (t.isAlive()) {
          log.warn("client thread {} did not stop within 5 s", t.getName());
        }
      }
    }
  }

  private static void closeQuietly(Socket s) {
    try {
      s.close();
    } catch (IOException e) {
      // Nothing more to do.
    }
  }
}
