package org.jaria.net.server;

import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.SocketChannel;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.net.protocol.FrameSplitter;
import org.jaria.net.protocol.Frames;

/**
 * One connected client, as the server sees it (ArNetworking's {@code ArServerClient}): who it is,
 * what it subscribed to and how much is waiting to be sent to it. Handlers receive it with each
 * request, for example to check {@link #hasGroupAccess}. Getters may be called from any thread.
 */
public final class ArServerClient {

  /** Where the conversation is. */
  enum State {
    AWAITING_HELLO,
    AWAITING_LOGIN,
    READY,
    CLOSED
  }

  /** A subscription: which data, how often, and what the client has been sent. */
  static final class Subscription {
    final DataEntry entry;
    volatile long intervalNanos;
    long nextDueNanos;
    long lastVersion = Long.MIN_VALUE;

    Subscription(DataEntry entry, long intervalNanos) {
      this.entry = entry;
      this.intervalNanos = intervalNanos;
    }
  }

  private final int id;
  private final String ip;
  final SocketChannel channel;
  SelectionKey key;
  final OutboundQueue out;
  final Map<Integer, Subscription> subscriptions = new ConcurrentHashMap<>();
  final AtomicInteger pendingCalls = new AtomicInteger();
  final AtomicBoolean writeScheduled = new AtomicBoolean();
  final AtomicBoolean dropRequested = new AtomicBoolean();
  private final AtomicLong bytesSent = new AtomicLong();
  private final AtomicLong bytesReceived = new AtomicLong();

  // I/O thread only.
  final FrameSplitter in;
  final ByteBuffer header = ByteBuffer.allocate(Frames.MAX_HEADER_BYTES);
  final ByteBuffer[] writeBufs = new ByteBuffer[2];
  Outgoing writing;
  boolean frameInProgress;
  byte[] nonce;
  Credentials pendingCredentials;
  long connectedNanos;
  long lastHeardNanos;
  long lastWriteProgressNanos;
  boolean closeAfterFlush;

  private volatile State state = State.AWAITING_HELLO;
  private volatile String clientName = "";
  private volatile String user = "";
  private volatile Credentials credentials;
  private volatile String closeReason;

  ArServerClient(int id, SocketChannel channel, String ip, long maxQueuedBytes, int maxFrame) {
    this.id = id;
    this.in = new FrameSplitter(4096, maxFrame);
    this.channel = channel;
    this.ip = ip;
    this.out = new OutboundQueue(maxQueuedBytes);
  }

  State state() {
    return state;
  }

  void setState(State s) {
    state = s;
  }

  void loggedIn(String name, Credentials c) {
    clientName = name;
    user = c.getUser();
    credentials = c;
    state = State.READY;
  }

  void setClientName(String name) {
    clientName = name;
  }

  void setCloseReason(String reason) {
    if (closeReason == null) {
      closeReason = reason;
    }
  }

  String pendingCloseReason() {
    return closeReason == null ? "closed by the server" : closeReason;
  }

  void countSent(long n) {
    bytesSent.addAndGet(n);
  }

  void countReceived(long n) {
    bytesReceived.addAndGet(n);
  }

  /** The server's number for this client (1, 2, ... in connection order). */
  public int getId() {
    return id;
  }

  /** The client's address. */
  public String getIpString() {
    return ip;
  }

  /** The name the client gave at login. */
  public String getClientName() {
    return clientName;
  }

  /** The user it logged in as ("" before login). */
  public String getUser() {
    return user;
  }

  /** Whether it has logged in (and not been closed). */
  public boolean isLoggedIn() {
    return state == State.READY;
  }

  /** Whether the connection has been closed. */
  public boolean isClosed() {
    return state == State.CLOSED;
  }

  /** Why the connection was closed, or null while open. */
  public String getCloseReason() {
    return state == State.CLOSED ? closeReason : null;
  }

  /** Whether the user may use data of {@code commandGroup}. */
  public boolean hasGroupAccess(String commandGroup) {
    Credentials c = credentials;
    return c != null && c.hasGroupAccess(commandGroup);
  }

  /** Bytes waiting to be sent to this client (replies and updates). */
  public long getQueuedBytes() {
    return out.queuedBytes();
  }

  /** Reply bytes waiting (the part limited by {@link ServerOptions#maxQueuedBytes()}). */
  public long getOwnedQueuedBytes() {
    return out.ownedBytes();
  }

  /** Most bytes ever waiting at once. */
  public long getPeakQueuedBytes() {
    return out.peakBytes();
  }

  /** Updates replaced by newer ones before the client took them (it reads slowly). */
  public long getCoalescedCount() {
    return out.coalescedCount();
  }

  /** Bytes written to the socket. */
  public long getBytesSent() {
    return bytesSent.get();
  }

  /** Bytes read from the socket. */
  public long getBytesReceived() {
    return bytesReceived.get();
  }

  /** The client's subscriptions: data name → interval. */
  public Map<String, Duration> getSubscriptions() {
    Map<String, Duration> m = new LinkedHashMap<>();
    for (Subscription s : subscriptions.values()) {
      m.put(s.entry.name(), Duration.ofNanos(s.intervalNanos));
    }
    return m;
  }

  @Override
  public String toString() {
    return "client " + id + " (" + (user.isEmpty() ? "" : user + "@") + ip + ")";
  }
}
