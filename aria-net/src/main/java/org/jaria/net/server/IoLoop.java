package org.jaria.net.server;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import org.jaria.net.ArNetPacket;
import org.jaria.net.ArNetPacketException;
import org.jaria.net.protocol.LoginDigest;
import org.jaria.net.protocol.NetError;
import org.jaria.net.protocol.Protocol;
import org.jaria.net.protocol.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's single I/O thread: accepts connections, reads and splits packets (handing each to
 * the {@link Dispatcher}), writes what the clients' queues hold without ever blocking, and enforces
 * the login, idle and stall timeouts. A client that breaks the protocol is closed here; nothing a
 * client does can block this thread or touch another client.
 */
final class IoLoop implements Runnable {

  private static final Logger log = LoggerFactory.getLogger(IoLoop.class);

  /** Longest wait in select, so timeouts are checked at least this often. */
  private static final long SELECT_MS = 50;

  /** Time given at shutdown to send the last SHUTDOWN packets. */
  private static final long SHUTDOWN_GRACE_MS = 200;

  private final ArServerBase server;
  private final ServerOptions options;
  private final Selector selector;
  private final ServerSocketChannel serverChannel;
  private final DatagramChannel udpChannel;
  private final ByteBuffer udpIn = ByteBuffer.allocate(ArNetPacket.MAX_LENGTH);
  private final Dispatcher dispatcher;
  private final ConcurrentLinkedQueue<ArServerClient> writeRequests = new ConcurrentLinkedQueue<>();
  private final ConcurrentLinkedQueue<Runnable> closeRequests = new ConcurrentLinkedQueue<>();
  private final List<ArServerClient> clients = new ArrayList<>();
  private volatile boolean stopping;
  private int nextId = 1;

  IoLoop(ArServerBase server, ServerOptions options, Dispatcher dispatcher) throws IOException {
    this.server = server;
    this.options = options;
    this.dispatcher = dispatcher;
    this.selector = Selector.open();
    this.serverChannel = ServerSocketChannel.open();
    try {
      serverChannel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
      InetSocketAddress bind = bindAddress();
      serverChannel.bind(bind, 64);
      serverChannel.configureBlocking(false);
      serverChannel.register(selector, SelectionKey.OP_ACCEPT);
    } catch (IOException e) {
      serverChannel.close();
      selector.close();
      throw new IOException(
          "cannot listen on port "
              + options.port()
              + " ("
              + e.getMessage()
              + "): is another server running there? Choose another port.",
          e);
    }
    this.udpChannel = openUdp();
  }

  private DatagramChannel openUdp() {
    if (!options.udp()) {
      return null;
    }
    DatagramChannel ch = null;
    try {
      // ArNetworking's UDP port has the TCP port's number.
      ch = DatagramChannel.open();
      ch.bind(new InetSocketAddress(serverChannel.socket().getInetAddress(), port()));
      ch.configureBlocking(false);
      ch.register(selector, SelectionKey.OP_READ, this);
      return ch;
    } catch (IOException e) {
      log.info("UDP port {} could not be opened ({}); clients will use TCP only", port(), e);
      if (ch != null) {
        closeQuietly(ch);
      }
      return null;
    }
  }

  /** The UDP port, 0 if none is open. */
  int udpPort() {
    return udpChannel == null ? 0 : port();
  }

  /** Whether the server listens on the loopback address only. */
  boolean isLoopbackOnly() {
    return serverChannel.socket().getInetAddress().isLoopbackAddress();
  }

  private InetSocketAddress bindAddress() throws IOException {
    String addr = options.bindAddress();
    if (addr == null) {
      return options.authenticator().isOpen()
          ? new InetSocketAddress(InetAddress.getLoopbackAddress(), options.port())
          : new InetSocketAddress(options.port());
    }
    return new InetSocketAddress(InetAddress.getByName(addr), options.port());
  }

  int port() {
    return serverChannel.socket().getLocalPort();
  }

  /** The address listened on; "0.0.0.0" for every interface (IPv4 and IPv6 alike). */
  String address() {
    InetAddress a = serverChannel.socket().getInetAddress();
    return a.isAnyLocalAddress() ? "0.0.0.0" : a.getHostAddress();
  }

  /** Asks the loop to stop; it closes every client and returns. */
  void stop() {
    stopping = true;
    selector.wakeup();
  }

  /** Asks the I/O thread to write {@code c}'s queue (from any thread). */
  void scheduleWrite(ArServerClient c, boolean wakeup) {
    if (c.writeScheduled.compareAndSet(false, true)) {
      writeRequests.add(c);
      if (wakeup) {
        selector.wakeup();
      }
    }
  }

  /** Wakes the I/O thread (after a batch of {@code scheduleWrite(c, false)}). */
  void wakeup() {
    selector.wakeup();
  }

  /** Asks the I/O thread to close {@code c} (from any thread). */
  void requestClose(ArServerClient c, NetError code, String reason) {
    closeRequests.add(() -> close(c, code, reason, true));
    selector.wakeup();
  }

  @Override
  public void run() {
    try {
      while (!stopping) {
        selector.select(SELECT_MS);
        for (SelectionKey k : selector.selectedKeys()) {
          handleKey(k);
        }
        selector.selectedKeys().clear();
        Runnable r;
        while ((r = closeRequests.poll()) != null) {
          r.run();
        }
        ArServerClient c;
        while ((c = writeRequests.poll()) != null) {
          c.writeScheduled.set(false);
          if (!c.isClosed()) {
            flush(c);
          }
        }
        checkTimeouts();
      }
    } catch (IOException | ClosedSelectorException e) {
      if (!stopping) {
        log.error("the server's I/O loop failed; no client can be served any more", e);
      }
    } catch (RuntimeException e) {
      log.error("the server's I/O loop failed; no client can be served any more", e);
    } finally {
      shutdown();
    }
  }

  private void handleKey(SelectionKey k) {
    if (!k.isValid()) {
      return;
    }
    if (k.isAcceptable()) {
      accept();
      return;
    }
    if (k.attachment() == this) {
      readUdp();
      return;
    }
    ArServerClient c = (ArServerClient) k.attachment();
    try {
      if (k.isReadable()) {
        read(c);
      }
      if (k.isValid() && k.isWritable() && !c.isClosed()) {
        flush(c);
      }
    } catch (ProtocolException e) {
      server.stats.malformed.increment();
      log.info("{}: {}; closing it", c, e.getMessage());
      close(c, e.getCode(), e.getMessage(), true);
    } catch (IOException e) {
      close(c, null, "connection lost: " + e.getMessage(), false);
    } catch (RuntimeException e) {
      // Whatever a client's bytes make the decoder do, only that client pays for it.
      server.stats.malformed.increment();
      log.info("{}: its packet could not be handled ({}); closing it", c, e.toString());
      close(c, NetError.MALFORMED, "a frame the server could not decode", true);
    }
  }

  private void accept() {
    while (true) {
      SocketChannel ch;
      try {
        ch = serverChannel.accept();
      } catch (IOException e) {
        log.warn("accept failed: {}", e.getMessage());
        return;
      }
      if (ch == null) {
        return;
      }
      String ip;
      try {
        ch.configureBlocking(false);
        ch.setOption(StandardSocketOptions.TCP_NODELAY, true);
        if (options.socketSendBuffer() > 0) {
          ch.setOption(StandardSocketOptions.SO_SNDBUF, options.socketSendBuffer());
        }
        ip = ((InetSocketAddress) ch.getRemoteAddress()).getAddress().getHostAddress();
      } catch (IOException e) {
        closeQuietly(ch);
        continue;
      }
      if (stopping) {
        closeQuietly(ch);
        return;
      }
      if (!admit(ip)) {
        closeQuietly(ch);
        continue;
      }
      long authKey;
      do {
        authKey = server.random.nextInt() & 0xFFFFFFFFL;
      } while (authKey == 0 || hasAuthKey(authKey));
      ArServerClient c =
          new ArServerClient(
              server,
              nextId++,
              ch,
              ip,
              options.maxQueuedBytes(),
              LoginDigest.newPasswordKey(server.random),
              authKey,
              server.random.nextInt() & 0x7FFFFFFF);
      long now = options.timeoutClock().nanoTime();
      c.connectedNanos = now;
      c.lastHeardNanos = now;
      c.lastWriteProgressNanos = now;
      try {
        c.key = ch.register(selector, SelectionKey.OP_READ, c);
      } catch (IOException e) {
        closeQuietly(ch);
        continue;
      }
      clients.add(c);
      server.addClient(c);
      server.stats.accepted.increment();
      log.debug("{} connected", c);
      // ArNetworking's server speaks first: its introduction carries the keys for the login.
      c.out.offer(Outgoing.frame(dispatcher.introduction(c, udpPort()).toWire()));
      flush(c);
    }
  }

  /**
   * Whether a connection from {@code ip} may wait to log in (see {@link PendingAdmission}); closes
   * the waiting connection it replaces.
   */
  private boolean admit(String ip) {
    List<ArServerClient> waiting = new ArrayList<>();
    List<PendingAdmission.Waiting> values = new ArrayList<>();
    for (ArServerClient o : clients) {
      if (!o.isLoggedIn() && !o.isClosed() && !o.closeAfterFlush) {
        waiting.add(o);
        values.add(
            new PendingAdmission.Waiting(
                o.getIpString(), o.connectedNanos, privileged(o.getIpString())));
      }
    }
    PendingAdmission.Decision d =
        PendingAdmission.admit(
            values,
            ip,
            privileged(ip),
            options.maxPendingLoginsPerAddress(),
            options.maxPendingLogins());
    if (!d.accept()) {
      // Sockets that never log in must not lock real users out: refuse the newcomer at once.
      server.stats.refusedPending.increment();
      log.info(
          "refused a connection from {}: already {} connections waiting to log in",
          ip,
          values.size());
      return false;
    }
    if (d.replaced() >= 0) {
      ArServerClient old = waiting.get(d.replaced());
      server.stats.replacedPending.increment();
      log.debug("{} replaced by a newer connection from {} before it logged in", old, ip);
      close(old, NetError.LOGIN_TIMEOUT, "replaced by a newer connection before logging in", false);
    }
    return true;
  }

  /** The loopback address, or an address somebody has logged in from. */
  private boolean privileged(String ip) {
    try {
      return InetAddress.getByName(ip).isLoopbackAddress() || server.loginLimiter().isKnown(ip);
    } catch (java.net.UnknownHostException e) {
      return false; // a literal address always parses; nothing else is privileged
    }
  }

  private void read(ArServerClient c) throws IOException, ProtocolException {
    int n = c.channel.read(c.in.buffer());
    if (n < 0) {
      close(c, null, "the client closed the connection", false);
      return;
    }
    c.countReceived(n);
    c.lastHeardNanos = options.timeoutClock().nanoTime();
    c.in.drain(p -> dispatcher.onPacket(c, p, false));
  }

  private boolean hasAuthKey(long k) {
    for (ArServerClient c : clients) {
      if (c.authKey == k) {
        return true;
      }
    }
    return false;
  }

  /**
   * One UDP datagram: a client's UDP introduction (its auth key) is answered with our UDP
   * introduction over UDP and a confirmation over TCP, as ArNetworking does; a packet from a
   * confirmed client's address is handled like one sent over TCP; anything else is counted and
   * dropped.
   */
  private void readUdp() {
    while (true) {
      udpIn.clear();
      SocketAddress from;
      try {
        from = udpChannel.receive(udpIn);
      } catch (IOException e) {
        log.debug("udp receive failed: {}", e.getMessage());
        return;
      }
      if (from == null) {
        return;
      }
      ArNetPacket p;
      try {
        p = ArNetPacket.fromWire(udpIn.array(), 0, udpIn.position());
      } catch (ArNetPacketException e) {
        server.stats.udpDropped.increment();
        continue;
      }
      handleUdp(p, (InetSocketAddress) from);
    }
  }

  private void handleUdp(ArNetPacket p, InetSocketAddress from) {
    if (p.getCommand() == Protocol.CLIENT_UDP_INTRODUCTION) {
      long key;
      try {
        key = p.bufToUByte4();
      } catch (ArNetPacketException e) {
        server.stats.udpDropped.increment();
        return;
      }
      for (ArServerClient c : clients) {
        if (c.authKey == key
            && c.isLoggedIn()
            && from.getAddress().getHostAddress().equals(c.getIpString())) {
          c.udpAddress = from;
          ArNetPacket intro = new ArNetPacket(Protocol.SERVER_UDP_INTRODUCTION);
          intro.byte4ToBuf(c.introKey);
          try {
            udpChannel.send(ByteBuffer.wrap(intro.toWire()), from);
          } catch (IOException e) {
            log.debug("udp send failed: {}", e.getMessage());
          }
          c.out.offer(Outgoing.frame(new ArNetPacket(Protocol.SERVER_UDP_CONFIRMATION).toWire()));
          flush(c);
          return;
        }
      }
      server.stats.udpDropped.increment();
      return;
    }
    for (ArServerClient c : clients) {
      if (from.equals(c.udpAddress) && c.isLoggedIn()) {
        try {
          dispatcher.onPacket(c, p, true);
        } catch (ProtocolException e) {
          server.stats.malformed.increment();
        }
        return;
      }
    }
    server.stats.udpDropped.increment();
  }

  /**
   * Whether {@code c}'s socket takes some of its waiting output now. Output queued by another
   * thread since the last write has not waited on the client yet (the time since the last write
   * progress says nothing about it), so a client is judged stalled only if its socket takes nothing
   * when tried.
   */
  private boolean flushedNow(ArServerClient c) {
    long before = c.lastWriteProgressNanos;
    flush(c);
    return c.isClosed() || c.lastWriteProgressNanos != before;
  }

  /** Writes as much of {@code c}'s queue as the socket takes now. */
  void flush(ArServerClient c) {
    try {
      long now = options.timeoutClock().nanoTime();
      while (true) {
        if (c.writing == null) {
          c.writing = c.out.start();
          if (c.writing == null) {
            c.lastWriteProgressNanos = now;
            setWriteInterest(c, false);
            if (c.closeAfterFlush) {
              close(c, null, c.pendingCloseReason(), false);
            }
            return;
          }
          c.writingBuf = c.writing.payload.duplicate();
          c.writingBuf.position(0);
        }
        long n = c.channel.write(c.writingBuf);
        if (n > 0) {
          c.countSent(n);
          c.lastWriteProgressNanos = now;
        }
        if (c.writingBuf.hasRemaining()) {
          setWriteInterest(c, true);
          return;
        }
        c.out.finished(c.writing);
        c.writing = null;
        c.writingBuf = null;
      }
    } catch (IOException e) {
      close(c, null, "connection lost while writing: " + e.getMessage(), false);
    }
  }

  private static void setWriteInterest(ArServerClient c, boolean on) {
    SelectionKey k = c.key;
    if (k != null && k.isValid()) {
      int ops = on ? SelectionKey.OP_READ | SelectionKey.OP_WRITE : SelectionKey.OP_READ;
      if (k.interestOps() != ops) {
        k.interestOps(ops);
      }
    }
  }

  private void checkTimeouts() {
    long now = options.timeoutClock().nanoTime();
    long login = options.loginTimeout().toNanos();
    long idle = options.idleTimeout().toNanos();
    long stall = options.stallTimeout().toNanos();
    for (ArServerClient c : new ArrayList<>(clients)) {
      if (c.isClosed()) {
        continue;
      }
      if (!c.isLoggedIn() && !c.closeAfterFlush && now - c.connectedNanos > login) {
        server.stats.loginTimeouts.increment();
        close(
            c,
            NetError.LOGIN_TIMEOUT,
            "did not log in within " + secs(options.loginTimeout()),
            true);
      } else if (c.isLoggedIn() && idle > 0 && now - c.lastHeardNanos > idle) {
        server.stats.droppedIdle.increment();
        close(c, NetError.IDLE, "sent nothing for " + secs(options.idleTimeout()), true);
      } else if (stall > 0
          && (c.writing != null || !c.out.isEmpty())
          && now - c.lastWriteProgressNanos > stall
          && !flushedNow(c)) {
        server.stats.droppedSlow.increment();
        close(
            c,
            NetError.TOO_SLOW,
            "took no data for " + secs(options.stallTimeout()) + " with data waiting",
            false);
      }
    }
  }

  /**
   * Closes {@code c}: optionally tries to send a SHUTDOWN packet first (logged-in clients) (without
   * waiting), then closes the socket, forgets its queue and subscriptions, and tells the listeners.
   */
  void close(ArServerClient c, NetError code, String reason, boolean sayWhy) {
    if (c.isClosed()) {
      return;
    }
    c.setCloseReason(reason);
    if (sayWhy && code != null && c.writing == null && c.isLoggedIn()) {
      try {
        // ArNetworking has no reason text for a close: the client is told to shut down.
        c.channel.write(ByteBuffer.wrap(new ArNetPacket(Protocol.SERVER_SHUTDOWN).toWire()));
      } catch (IOException e) {
        // Best effort: the connection is going anyway.
      }
    }
    c.setState(ArServerClient.State.CLOSED);
    if (c.key != null) {
      c.key.cancel();
    }
    closeQuietly(c.channel);
    c.out.clear();
    c.requests.clear();
    clients.remove(c);
    server.removeClient(c, reason);
    log.debug("{} closed: {}", c, reason);
  }

  private void shutdown() {
    for (ArServerClient c : new ArrayList<>(clients)) {
      if (c.isLoggedIn()) {
        c.out.offer(Outgoing.frame(new ArNetPacket(Protocol.SERVER_SHUTDOWN).toWire()));
        c.closeAfterFlush = true;
        c.setCloseReason("the server is shutting down");
        flush(c);
      }
    }
    long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(SHUTDOWN_GRACE_MS);
    try {
      while (!clients.isEmpty() && System.nanoTime() < end && selector.isOpen()) {
        selector.select(10);
        for (SelectionKey k : selector.selectedKeys()) {
          if (k.isValid() && k.isWritable()) {
            flush((ArServerClient) k.attachment());
          }
        }
        selector.selectedKeys().clear();
      }
    } catch (IOException | ClosedSelectorException e) {
      // Closing anyway.
    }
    for (ArServerClient c : new ArrayList<>(clients)) {
      close(c, null, "the server is shutting down", false);
    }
    closeQuietly(serverChannel);
    if (udpChannel != null) {
      closeQuietly(udpChannel);
    }
    try {
      selector.close();
    } catch (IOException e) {
      log.debug("closing the selector: {}", e.getMessage());
    }
  }

  /** "10 s", "0.5 s": a duration for people. */
  static String secs(java.time.Duration d) {
    return java.math.BigDecimal.valueOf(d.toMillis(), 3).stripTrailingZeros().toPlainString()
        + " s";
  }

  private static void closeQuietly(java.io.Closeable c) {
    try {
      c.close();
    } catch (IOException e) {
      // Nothing more to do with a socket that will not close.
    }
  }
}
