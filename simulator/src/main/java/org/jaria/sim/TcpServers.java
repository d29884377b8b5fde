package org.jaria.sim;

import java.io.IOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.Iterator;
import java.util.List;
import java.util.function.BiConsumer;
import org.jaria.clock.Clock;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.NioSocketConnection;
import org.jaria.sim.server.SessionHost;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robots' listening TCP ports. Nothing here has a thread: the world thread checks for new
 * clients on every tick with a non-blocking select, so a simulator with a hundred robots still has
 * one thread.
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
  static TcpServers openAll(List<RobotSlot> slots, java.net.InetAddress bindAddress)
      throws IOException {
    TcpServers servers = new TcpServers(bindAddress);
    try {
      for (RobotSlot s : slots) {
        servers.bind(s, s.requestedPort);
      }
      return servers;
    } catch (IOException e) {
      servers.close();
      for (RobotSlot t : slots) {
        t.server = null;
        t.boundPort = -1;
      }
      throw e;
    }
  }

  /** Gives a newly accepted client to its robot, or refuses it if the robot has one already. */
  static void attach(RobotSlot slot, SocketChannel c, Clock clock, SessionHost host) {
    if (slot.session != null) {
      log.warn("robot {} already has a client; refusing another connection", slot.body.name());
      closeQuietly(c);
      return;
    }
    try {
      slot.session =
          new ArcosSession(slot.body, new NioSocketConnection(c, clock), host, slot.drops);
      slot.sessionsStarted++;
      log.info("robot {}: client connected ({})", slot.body.name(), c.getRemoteAddress());
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
    ServerSocketChannel ch = ServerSocketChannel.open();
    try {
      ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
      ch.bind(new InetSocketAddress(bindAddress, port), 8);
      ch.configureBlocking(false);
      ch.register(selector, SelectionKey.OP_ACCEPT, slot);
    } catch (BindException e) {
      closeQuietly(ch);
      throw new IOException(
          "TCP port "
              + port
              + " for robot "
              + slot.body.name()
              + " is in use ("
              + e.getMessage()
              + "): is another simulator running? Stop it or choose another --port",
          e);
    } catch (IOException e) {
      closeQuietly(ch);
      throw e;
    }
    slot.server = ch;
    slot.boundPort = ((InetSocketAddress) ch.getLocalAddress()).getPort();
    log.info("robot {} listens on TCP port {}", slot.body.name(), slot.boundPort);
  }

  /** Opens the port of a robot added while listening. */
  void bindLate(RobotSlot slot) {
    try {
      bind(slot, slot.requestedPort);
    } catch (IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
  }

  /** Accepts every waiting client and hands it to {@code accepted} (never blocks). */
  void acceptPending(BiConsumer<RobotSlot, SocketChannel> accepted) {
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
      RobotSlot slot = (RobotSlot) key.attachment();
      ServerSocketChannel ch = (ServerSocketChannel) key.channel();
      try {
        SocketChannel c;
        while ((c = ch.accept()) != null) {
          accepted.accept(slot, c);
        }
      } catch (IOException e) {
        log.warn("accepting a client for {} failed: {}", slot.body.name(), e.getMessage());
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
