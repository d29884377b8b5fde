package org.jaria.net.client;

import java.time.Duration;

/**
 * How an {@link ArClientBase} connects.
 *
 * @param name the client's name, for logs and thread names
 * @param connectTimeout time to connect and log in
 * @param requestTimeout time a {@link ArClientBase#requestOnce} waits for its reply
 * @param serverKey ArNetworking's server key, if the server was given one ("" as in ARIA)
 */
public record ClientOptions(
    String name, Duration connectTimeout, Duration requestTimeout, String serverKey) {

  /** Checks the options. */
  public ClientOptions {
    if (name == null || serverKey == null) {
      throw new IllegalArgumentException("the client needs a name and a server key (\"\")");
    }
    if (connectTimeout.isNegative()
        || connectTimeout.isZero()
        || requestTimeout.isNegative()
        || requestTimeout.isZero()) {
      throw new IllegalArgumentException("timeouts must be positive");
    }
  }

  /** 5 s to connect, 10 s per request, no server key. */
  public static ClientOptions defaults(String name) {
    return new ClientOptions(name, Duration.ofSeconds(5), Duration.ofSeconds(10), "");
  }

  /** A copy with another request timeout. */
  public ClientOptions withRequestTimeout(Duration d) {
    return new ClientOptions(name, connectTimeout, d, serverKey);
  }
}
