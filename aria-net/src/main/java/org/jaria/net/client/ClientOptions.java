package org.jaria.net.client;

import java.time.Duration;

/**
 * Settings of an {@link ArClientBase}.
 *
 * @param name the name the client gives the server (shown in its logs)
 * @param connectTimeout time to open the connection and to log in
 * @param requestTimeout time a request waits for its reply before failing
 * @param pingInterval a ping is sent when nothing was sent for this long (keeps the server's idle
 *     timeout away and measures latency)
 * @param readTimeout the connection is considered lost when nothing arrives for this long (must be
 *     longer than the ping interval)
 * @param maxFrame largest frame accepted from the server, bytes
 * @param maxPayload largest reassembled reply or update, bytes
 * @param sendQueue frames waiting to be written; beyond it requests fail at once
 */
public record ClientOptions(
    String name,
    Duration connectTimeout,
    Duration requestTimeout,
    Duration pingInterval,
    Duration readTimeout,
    int maxFrame,
    int maxPayload,
    int sendQueue) {

  /** Checks the values. */
  public ClientOptions {
    if (name == null) {
      throw new IllegalArgumentException("the client needs a name");
    }
    if (readTimeout.compareTo(pingInterval) <= 0) {
      throw new IllegalArgumentException("the read timeout must be longer than the ping interval");
    }
    if (maxFrame < 1024 || maxPayload < maxFrame || sendQueue < 1) {
      throw new IllegalArgumentException("frame, payload and queue limits are too small");
    }
  }

  /**
   * Defaults: 5 s to connect, 10 s per request, a ping every 5 s, lost after 15 s of silence, 4 MiB
   * frames, 64 MiB payloads, 1024 frames waiting to be sent.
   */
  public static ClientOptions defaults(String name) {
    return new ClientOptions(
        name,
        Duration.ofSeconds(5),
        Duration.ofSeconds(10),
        Duration.ofSeconds(5),
        Duration.ofSeconds(15),
        4 << 20,
        64 << 20,
        1024);
  }

  /** The same options with another request timeout. */
  public ClientOptions withRequestTimeout(Duration d) {
    return new ClientOptions(
        name, connectTimeout, d, pingInterval, readTimeout, maxFrame, maxPayload, sendQueue);
  }
}
