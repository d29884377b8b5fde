package org.jaria.web.server;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Objects;

/**
 * How the web view serves.
 *
 * @param bind the address to listen on ("127.0.0.1": this computer only)
 * @param port the TCP port (0: any free one)
 * @param allowControl whether viewers may drive the robot and run the simulation
 * @param token the secret every request must carry as {@code ?token=...}, or null for none (a
 *     server bound beyond the loopback always has one)
 * @param maxClients most WebSocket clients at once
 * @param rateHz frames a second
 * @param maxMessageBytes largest message a client may send; a larger one closes its connection
 * @param maxQueuedBytes bytes a client may have waiting to be sent before its messages are dropped
 * @param slowClientMillis how long a client may keep dropping messages before it is disconnected
 * @param serverName the name in serverInfo
 */
public record WebOptions(
    String bind,
    int port,
    boolean allowControl,
    String token,
    int maxClients,
    double rateHz,
    int maxMessageBytes,
    int maxQueuedBytes,
    long slowClientMillis,
    String serverName) {

  /** The default port of {@code jaria web}. */
  public static final int DEFAULT_PORT = 8088;

  /** Checks; a non-loopback address without a token gets a new random one. */
  public WebOptions {
    Objects.requireNonNull(bind, "bind");
    Objects.requireNonNull(serverName, "serverName");
    if (port < 0 || port > 0xFFFF) {
      throw new IllegalArgumentException("the web port is 0..65535 (0: any free one), not " + port);
    }
    if (maxClients < 1 || maxClients > 1000) {
      throw new IllegalArgumentException("at most 1..1000 web clients, not " + maxClients);
    }
    if (!(rateHz > 0 && rateHz <= 60)) {
      throw new IllegalArgumentException("the web view's rate is above 0 and at most 60 Hz");
    }
    if (maxMessageBytes < 1024 || maxQueuedBytes < 65536 || slowClientMillis < 100) {
      throw new IllegalArgumentException(
          "limits too small: messages of 1 KiB, queues of 64 KiB and 100 ms at least");
    }
    if (token == null && !isLoopback(bind)) {
      token = newToken();
    }
  }

  /** Loopback only, port {@code port}, read-only, the usual limits. */
  public static WebOptions loopback(int port) {
    return new WebOptions(
        "127.0.0.1", port, false, null, 16, 10, 65536, 4 << 20, 3000, "JAria web view");
  }

  /** These options with control allowed (or not). */
  public WebOptions withControl(boolean allow) {
    return new WebOptions(
        bind,
        port,
        allow,
        token,
        maxClients,
        rateHz,
        maxMessageBytes,
        maxQueuedBytes,
        slowClientMillis,
        serverName);
  }

  /** These options bound to {@code address} (a token is made unless it is a loopback address). */
  public WebOptions withBind(String address) {
    return new WebOptions(
        address,
        port,
        allowControl,
        isLoopback(address) ? token : null,
        maxClients,
        rateHz,
        maxMessageBytes,
        maxQueuedBytes,
        slowClientMillis,
        serverName);
  }

  /** These options with other limits. */
  public WebOptions withLimits(int clients, int messageBytes, int queuedBytes, long slowMillis) {
    return new WebOptions(
        bind,
        port,
        allowControl,
        token,
        clients,
        rateHz,
        messageBytes,
        queuedBytes,
        slowMillis,
        serverName);
  }

  /** These options with another rate. */
  public WebOptions withRate(double hz) {
    return new WebOptions(
        bind,
        port,
        allowControl,
        token,
        maxClients,
        hz,
        maxMessageBytes,
        maxQueuedBytes,
        slowClientMillis,
        serverName);
  }

  /** These options with another name. */
  public WebOptions withName(String name) {
    return new WebOptions(
        bind,
        port,
        allowControl,
        token,
        maxClients,
        rateHz,
        maxMessageBytes,
        maxQueuedBytes,
        slowClientMillis,
        name);
  }

  /** Whether {@code address} names this computer only (127.x.x.x, ::1, localhost). */
  public static boolean isLoopback(String address) {
    try {
      return InetAddress.getByName(address).isLoopbackAddress();
    } catch (UnknownHostException e) {
      return false;
    }
  }

  private static String newToken() {
    byte[] b = new byte[16];
    new SecureRandom().nextBytes(b);
    return HexFormat.of().formatHex(b);
  }

  @Override
  public String toString() {
    // The token is a secret: never in a log line.
    return "WebOptions[" + bind + ":" + port + (token == null ? "" : ", token set") + "]";
  }
}
