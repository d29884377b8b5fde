package org.jaria.sim.devices;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArTcpConnection;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An emulated device on a TCP port (as behind a serial-to-Ethernet adapter): each accepted
 * connection gets a fresh device from the factory, so a driver that lost its device can connect
 * again. Listens on the loopback interface only.
 */
public final class DeviceTcpServer implements AutoCloseable {

  /** Makes the device for one accepted connection (not yet started). */
  @FunctionalInterface
  public interface Factory {
    /** The device for connection number {@code index} (0 for the first). */
    EmulatedDevice create(ArDeviceConnection connection, int index) throws IOException;
  }

  private static final Logger log = LoggerFactory.getLogger(DeviceTcpServer.class);

  private final ServerSocket server;
  private final Factory factory;
  private final Thread acceptor;

  /** Devices started so far. Guarded by {@code this}. */
  @GuardedBy("this")
  private final List<EmulatedDevice> devices = new ArrayList<>();

  /**
   * Listens on {@code port} (0 for any free port) of the loopback interface.
   *
   * @throws IOException if the port cannot be opened
   */
  public DeviceTcpServer(int port, Factory factory) throws IOException {
    this.server = new ServerSocket(port, 4, InetAddress.getLoopbackAddress());
    this.factory = factory;
    this.acceptor = new Thread(this::acceptLoop, "device-tcp-" + server.getLocalPort());
    this.acceptor.setDaemon(true);
    this.acceptor.start();
  }

  /** The port it listens on. */
  public int getPort() {
    return server.getLocalPort();
  }

  private void acceptLoop() {
    int index = 0;
    while (!server.isClosed()) {
      try {
        Socket s = server.accept();
        EmulatedDevice d = factory.create(ArTcpConnection.wrap(s, Clock.system()), index++);
        synchronized (this) {
          devices.add(d);
        }
        d.start();
      } catch (IOException e) {
        if (!server.isClosed()) {
          log.warn("device server on port {}: {}", getPort(), e.getMessage());
        }
      }
    }
  }

  /** The devices started so far, oldest first. */
  public synchronized List<EmulatedDevice> getDevices() {
    return List.copyOf(devices);
  }

  @Override
  public void close() {
    try {
      server.close();
    } catch (IOException e) {
      log.debug("closing device server: {}", e.getMessage());
    }
    try {
      acceptor.join(2000);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    for (EmulatedDevice d : getDevices()) {
      d.close();
    }
  }
}
