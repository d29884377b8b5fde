package org.jaria.acts.server;

import org.jaria.acts.ActsProtocol;

/**
 * How an {@link ActsServer} listens and paces itself.
 *
 * @param bindHost address to listen on: {@code "127.0.0.1"} (the default) for this computer only,
 *     as JAria's guiServer without a login (the ACTS protocol has none: whoever reaches the port
 *     reads the blobs); {@code "0.0.0.0"} or empty for every interface, as ACTS itself
 * @param port TCP port, 0 for any free port (see {@link ActsServer#getPort()})
 * @param maxFps most frames processed per second (ACTS's {@code -R}); 0 for no limit
 * @param maxClients most clients connected at once; more are refused (closed at once)
 * @param quitOnRequest whether a client's quit request ({@code '1'}) stops the whole server, as it
 *     stops ACTS; if false it only ends that client's connection
 * @param idleTimeoutMillis a client that neither sends a byte nor takes a reply for this long is
 *     disconnected, ms (default 30000): covers clients that only connect, clients that stop reading
 *     and peers that vanished without closing (half-open connections)
 */
public record ServerSettings(
    String bindHost,
    int port,
    int maxFps,
    int maxClients,
    boolean quitOnRequest,
    int idleTimeoutMillis) {

  /** Default idle timeout, ms. */
  public static final int DEFAULT_IDLE_TIMEOUT_MILLIS = 30_000;

  /**
   * This computer only (127.0.0.1), port 5001, 30 frames/s, 16 clients, quit requests end only the
   * client, idle clients dropped after 30 s.
   */
  public static final ServerSettings DEFAULT =
      new ServerSettings(
          "127.0.0.1", ActsProtocol.DEFAULT_PORT, 30, 16, false, DEFAULT_IDLE_TIMEOUT_MILLIS);

  /** Settings with the default idle timeout. */
  public ServerSettings(
      String bindHost, int port, int maxFps, int maxClients, boolean quitOnRequest) {
    this(bindHost, port, maxFps, maxClients, quitOnRequest, DEFAULT_IDLE_TIMEOUT_MILLIS);
  }

  /** Checks the ranges. */
  public ServerSettings {
    if (bindHost == null) {
      bindHost = "";
    }
    if (port < 0 || port > 65535) {
      throw new IllegalArgumentException("port must be 0..65535, got " + port);
    }
    if (maxFps < 0 || maxFps > 10_000) {
      throw new IllegalArgumentException("max frames per second must be 0..10000, got " + maxFps);
    }
    if (maxClients < 1 || maxClients > 1024) {
      throw new IllegalArgumentException("max clients must be 1..1024, got " + maxClients);
    }
    if (idleTimeoutMillis < 1) {
      throw new IllegalArgumentException(
          "the idle timeout must be at least 1 ms, got " + idleTimeoutMillis);
    }
  }

  /** These settings with another bind address and port. */
  public ServerSettings withAddress(String host, int p) {
    return new ServerSettings(host, p, maxFps, maxClients, quitOnRequest, idleTimeoutMillis);
  }

  /** These settings with another frame rate limit. */
  public ServerSettings withMaxFps(int fps) {
    return new ServerSettings(bindHost, port, fps, maxClients, quitOnRequest, idleTimeoutMillis);
  }

  /** These settings with another client limit. */
  public ServerSettings withMaxClients(int n) {
    return new ServerSettings(bindHost, port, maxFps, n, quitOnRequest, idleTimeoutMillis);
  }

  /** These settings with quit requests stopping (or not) the server. */
  public ServerSettings withQuitOnRequest(boolean quit) {
    return new ServerSettings(bindHost, port, maxFps, maxClients, quit, idleTimeoutMillis);
  }

  /** These settings with another idle timeout, ms. */
  public ServerSettings withIdleTimeoutMillis(int ms) {
    return new ServerSettings(bindHost, port, maxFps, maxClients, quitOnRequest, ms);
  }
}
