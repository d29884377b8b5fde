package org.jaria.sim;

import java.io.IOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import org.jaria.clock.Clock;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.ClientKind;
import org.jaria.sim.server.NioSocketConnection;
import org.jaria.sim.server.SessionHost;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robots' and robot factories' listening TCP ports. Nothing here has a thread: the world thread
 * checks for new clients on every tick with a non-blocking select, so a simulator with a hundred
 * robots still has one thread.
 */
final class TcpServers implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(TcpServers.class);

  private final Selector selector;

  /** The interface to listen on; null for every interface. */
  private final java.net.InetAddress bindAddress;

  TcpServers(java.net.InetAddress bindAddress) throws IOException {
    this.bindAddress = bindAddress;
    selector = Selector.open();
  }

  /**
   * Opens every robot's port (on {@code bindAddress} only, unless it is null); on failure closes
   * those already opened.
   *
   * @throws IOException naming the port that is taken
   */
  static TcpServers openAll(
      List<RobotSlot> slots, List<RobotFactory> factories, java.net.InetAddress bindAddress)
      throws IOException {
    TcpServers servers = new TcpServers(bindAddress);
    try {
      for (RobotFactory f : factories) {
        servers.bind(f);
      }
      for (RobotSlot s : slots) {
        if (s.factory == null) {
          servers.bind(s, s.requestedPort);
        }
      }
      return servers;
    } catch (IOException e) {
      servers.close();
      for (RobotSlot t : slots) {
        t.server = null;
        t.boundPort = -1;
      }
      for (RobotFactory f : factories) {
        f.boundPort = -1;
      }
      throw e;
    }
  }

  /**
   * Gives a newly accepted client to its robot. If the robot still has a client, that client is
   * checked first (it may just have left: ARIA's disconnect and a new connect can arrive in the
   * same tick); if it is still there, the newcomer waits (one per robot, see {@link #serveWaiting})
   * and any further one is refused.
   */
  static void attach(RobotSlot slot, SocketChannel c, Clock clock, SessionHost host) {
    long now = clock.nanoTime();
    slot.poll(now);
    if (slot.session == null) {
      start(slot, c, clock, host);
    } else if (slot.waiting == null) {
      slot.waiting = c;
      slot.waitingSinceNanos = now;
    } else {
      refuse(slot, c, now, "it already has a client and another is waiting");
    }
  }

  /**
   * Hands the waiting client over once its robot is free; refuses it if the robot is still taken
   * after the handshake timeout.
   */
  static void serveWaiting(RobotSlot slot, Clock clock, SessionHost host) {
    SocketChannel c = slot.waiting;
    if (c == null) {
      return;
    }
    long now = clock.nanoTime();
    if (slot.session == null) {
      slot.waiting = null;
      start(slot, c, clock, host);
    } else if (now - slot.waitingSinceNanos
        > TimeUnit.MILLISECONDS.toNanos(host.handshakeTimeoutMillis())) {
      slot.waiting = null;
      refuse(slot, c, now, "it still has a client");
    }
  }

  /** Starts a session between {@code slot}'s robot and the client {@code c}. */
  static void start(RobotSlot slot, SocketChannel c, Clock clock, SessionHost host) {
    try {
      SocketAddress remote = c.getRemoteAddress();
      ClientKind kind = ClientKind.ofTcpPeer(remote);
      slot.session =
          new ArcosSession(slot.body, new NioSocketConnection(c, clock), host, slot.drops, kind);
      slot.sessionsStarted++;
      log.info("robot {}: client connected ({})", slot.body.name(), remote);
    } catch (IOException e) {
      log.warn("robot {}: could not set up the connection: {}", slot.body.name(), e.getMessage());
      closeQuietly(c);
    }
  }

  /** Closes a client the robot cannot take; counted always, logged rate-limited. */
  private static void refuse(RobotSlot slot, SocketChannel c, long now, String why) {
    closeQuietly(c);
    slot.refused++;
    long unlogged = slot.refusalLog.record(now);
    if (unlogged == 0) {
      log.warn("robot {}: connection refused: {}", slot.body.name(), why);
    } else if (unlogged > 0) {
      log.warn(
          "robot {}: connection refused: {} ({} more refused since the last line)",
          slot.body.name(),
          why,
          unlogged);
    }
  }

  /**
   * Opens {@code slot}'s port.
   *
   * @throws IOException naming the port and what to do if it is taken
   */
  void bind(RobotSlot slot, int port) throws IOException {
    ServerSocketChannel ch = open(port, slot, "robot " + slot.body.name());
    slot.server = ch;
    slot.boundPort = ((InetSocketAddress) ch.getLocalAddress()).getPort();
    log.info("robot {} listens on TCP port {}", slot.body.name(), slot.boundPort);
  }

  /**
   * Opens a robot factory's port.
   *
   * @throws IOException naming the port and what to do if it is taken
   */
  void bind(RobotFactory f) throws IOException {
    ServerSocketChannel ch = open(f.requestedPort, f, "the " + f.getModel() + " robot factory");
    f.boundPort = ((InetSocketAddress) ch.getLocalAddress()).getPort();
    log.info("robot factory for {} listens on TCP port {}", f.getModel(), f.boundPort);
  }

  /** Opens a non-blocking listening port whose clients go to {@code owner}. */
  private ServerSocketChannel open(int port, Object owner, String what) throws IOException {
    ServerSocketChannel ch = ServerSocketChannel.open();
    try {
      ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
      // a factory expects many clients at once (each gets a robot); a robot, one
      ch.bind(new InetSocketAddress(bindAddress, port), owner instanceof RobotFactory ? 64 : 8);
      ch.configureBlocking(false);
      ch.register(selector, SelectionKey.OP_ACCEPT, owner);
      return ch;
    } catch (BindException e) {
      closeQuietly(ch);
      throw new IOException(
          "TCP port "
              + port
              + " for "
              + what
              + " is in use ("
              + e.getMessage()
              + "): is another simulator running? Stop it or choose another --port",
          e);
    } catch (IOException e) {
      closeQuietly(ch);
      throw e;
    }
  }

  /** Opens the port of a robot added while listening. */
  void bindLate(RobotSlot slot) {
    try {
      bind(slot, slot.requestedPort);
    } catch (IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
  }

  /**
   * Accepts every waiting client and hands it to {@code robotClient} or, if it came to a robot
   * factory's port, to {@code factoryClient} (never blocks).
   */
  void acceptPending(
      BiConsumer<RobotSlot, SocketChannel> robotClient,
      BiConsumer<RobotFactory, SocketChannel> factoryClient) {
    try {
      if (selector.selectNow() == 0) {
        return;
      }
    } catch (IOException e) {
      log.warn("checking for new clients failed: {}", e.getMessage());
      return;
    }
    Iterator<SelectionKey> it = selector.selectedKeys().iterator();
    while (it.hasNext()) {
      SelectionKey key = it.next();
      it.remove();
      if (!key.isValid()) {
        continue;
      }
      Object owner = key.attachment();
      ServerSocketChannel ch = (ServerSocketChannel) key.channel();
      try {
        SocketChannel c;
        while ((c = ch.accept()) != null) {
          if (owner instanceof RobotFactory f) {
            factoryClient.accept(f, c);
          } else {
            robotClient.accept((RobotSlot) owner, c);
          }
        }
      } catch (IOException e) {
        log.warn("accepting a client for {} failed: {}", owner, e.getMessage());
      }
    }
  }

  /** Closes one robot's port. */
  static void unbind(RobotSlot slot) {
    if (slot.waiting != null) {
      closeQuietly(slot.waiting);
      slot.waiting = null;
    }
    if (slot.server != null) {
      closeQuietly(slot.server);
      slot.server = null;
    }
  }

  private static void closeQuietly(java.io.Closeable c) {
    try {
      c.close();
    } catch (IOException ignored) {
      // closing anyway
    }
  }

  @Override
  public void close() {
    for (SelectionKey k : selector.keys()) {
      closeQuietly(k.channel());
    }
    closeQuietly(selector);
  }
}
