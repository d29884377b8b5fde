package org.jaria.net.server;

import java.net.InetSocketAddress;
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
import org.jaria.net.ArNetPacket;
import org.jaria.net.protocol.PacketSplitter;

/**
 * One connected client, as the server sees it (ArNetworking's {@code ArServerClient}): who it is,
 * what it requested and how much is waiting to be sent to it. Handlers receive it with each
 * request, for example to check {@link #hasGroupAccess}. Getters may be called from any thread.
 */
public final class ArServerClient {

  /** Where the conversation is. */
  enum State {
    /** The server sent its introduction and waits for the client's. */
    SENT_INTRO,
    /** Logged in. */
    CONNECTED,
    CLOSED
  }

  /**
   * A request (ArNetworking's REQUEST): which data, how often (negative: only when it changes or is
   * broadcast), its arguments, and what the client has been sent.
   */
  static final class Request {
    final DataEntry entry;
    final long intervalNanos;
    final byte[] args;
    long nextDueNanos;
    volatile long lastVersion = Long.MIN_VALUE;

    /** A handler run for this request has not finished yet (so runs never pile up). */
    final AtomicBoolean running = new AtomicBoolean();

    Request(DataEntry entry, long intervalNanos, byte[] args) {
      this.entry = entry;
      this.intervalNanos = intervalNanos;
      this.args = args;
    }

    boolean periodic() {
      return intervalNanos >= 0;
    }
  }

  private final ArServerBase server;
  private final int id;
  private final String ip;
  final SocketChannel channel;
  SelectionKey key;
  final OutboundQueue out;
  final Map<Integer, Request> requests = new ConcurrentHashMap<>();
  final AtomicInteger pendingCalls = new AtomicInteger();

  /** Held while one of this client's worker handlers runs (see ArServerBase.runCall). */
  final Object handlerLock = new Object();

  final AtomicBoolean writeScheduled = new AtomicBoolean();
  final AtomicBoolean dropRequested = new AtomicBoolean();
  private final AtomicLong bytesSent = new AtomicLong();
  private final AtomicLong bytesReceived = new AtomicLong();

  // Set when the connection is made, then read-only.
  final String passwordKey;
  final long authKey;
  final int introKey;

  // I/O thread only.
  final PacketSplitter in = new PacketSplitter();
  ByteBuffer writingBuf;
  Outgoing writing;
  long connectedNanos;
  long lastHeardNanos;
  long lastWriteProgressNanos;
  boolean closeAfterFlush;
  volatile InetSocketAddress udpAddress;
  volatile boolean tcpOnly = true;

  /** The client wants an empty packet for commands that return nothing (a JAria client). */
  volatile boolean wantsAcks;

  private volatile State state = State.SENT_INTRO;
  private volatile String user = "";
  private volatile Credentials credentials;
  private volatile String closeReason;

  ArServerClient(
      ArServerBase server,
      int id,
      SocketChannel channel,
      String ip,
      long maxQueuedBytes,
      String passwordKey,
      long authKey,
      int introKey) {
    this.server = server;
    this.id = id;
    this.channel = channel;
    this.ip = ip;
    this.out = new OutboundQueue(maxQueuedBytes);
    this.passwordKey = passwordKey;
    this.authKey = authKey;
    this.introKey = introKey;
  }

  State state() {
    return state;
  }

  void setState(State s) {
    state = s;
  }

  void loggedIn(Credentials c) {
    user = c.getUser();
    credentials = c;
    state = State.CONNECTED;
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

  /**
   * Sends {@code packet} to this client (ArNetworking's {@code sendPacketTcp}): for handlers that
   * answer with several packets, such as {@code getMap}. Set the packet's command to the data's
   * number ({@link ArServerBase#findCommandFromName}).
   *
   * @throws IllegalArgumentException if the packet has no command
   */
  public void sendPacketTcp(ArNetPacket packet) {
    if (packet.getCommand() == 0) {
      throw new IllegalArgumentException("set the packet's command before sending it");
    }
    server.sendPacket(this, packet);
  }

  /** The server's number for this client (1, 2, ... in connection order). */
  public int getId() {
    return id;
  }

  /** The client's address. */
  public String getIpString() {
    return ip;
  }

  /** The user it logged in as ("" before login, or on an open server where none was given). */
  public String getUser() {
    return user;
  }

  /** Whether it has logged in (and not been closed). */
  public boolean isLoggedIn() {
    return state == State.CONNECTED;
  }

  /** Whether the connection has been closed. */
  public boolean isClosed() {
    return state == State.CLOSED;
  }

  /** Whether the client confirmed a UDP path (else everything goes over TCP). */
  public boolean isUdpConfirmed() {
    return !tcpOnly;
  }

  /** Why the connection was closed, or null while open. */
  public String getCloseReason() {
    return state == State.CLOSED ? closeReason : null;
  }

  /** Whether the user may use data of {@code commandGroup} (ArNetworking's group check). */
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

  /**
   * The client's requests: data name → interval (negative: only when it changes or is broadcast).
   */
  public Map<String, Duration> getSubscriptions() {
    Map<String, Duration> m = new LinkedHashMap<>();
    for (Request s : requests.values()) {
      m.put(s.entry.name(), Duration.ofNanos(s.intervalNanos));
    }
    return m;
  }

  @Override
  public String toString() {
    return "client " + id + " (" + (user.isEmpty() ? "" : user + "@") + ip + ")";
  }
}
