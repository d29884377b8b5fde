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
import java.util.function.BiConsumer;
import org.jaria.clock.Clock;
import org.jaria.sim.server.ClientKind;
import org.jaria.sim.server.NioSocketConnection;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robots' and robot factories' listening TCP ports. Nothing here has a thread: the world thread
 * checks for new clients on every tick with a non-blocking select, so a simulator with a hundred
 * robots still has one thread.
 */
final class TcpServers implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(TcpServers.class);

  /**
   * Connections the system may complete before the world thread accepts them (it accepts every
   * tick). A short queue makes a burst of connects wait for the system's SYN retry (a second or
   * more each) however fast the world accepts; the system may cap it (Linux: net.core.somaxconn).
   */
  static final int LISTEN_BACKLOG = 1024;

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
        f.setBoundPort(-1);
      }
      throw e;
    }
  }

  /**
   * Gives a newly accepted client to its robot, where it waits beside the robot until it completes
   * the handshake (see {@link org.jaria.sim.server.RobotClients} for who holds the robot).
   */
  static void attach(RobotSlot slot, SocketChannel c, Clock clock) {
    try {
      SocketAddress remote = c.getRemoteAddress();
      slot.clients.attach(new NioSocketConnection(c, clock), ClientKind.ofTcpPeer(remote));
      log.debug("robot {}: client connected ({})", slot.body.name(), remote);
    } catch (IOException e) {
      log.warn("robot {}: could not set up the connection: {}", slot.body.name(), e.getMessage());
      closeQuietly(c);
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
    int port = ((InetSocketAddress) ch.getLocalAddress()).getPort();
    f.setBoundPort(port);
    log.info("robot factory for {} listens on TCP port {}", f.getModel(), port);
  }

  /** Opens a non-blocking listening port whose clients go to {@code owner}. */
  private ServerSocketChannel open(int port, Object owner, String what) throws IOException {
    ServerSocketChannel ch = ServerSocketChannel.open();
    try {
      ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
      ch.bind(new InetSocketAddress(bindAddress, port), LISTEN_BACKLOG);
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
