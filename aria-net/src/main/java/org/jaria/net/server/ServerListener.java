package org.jaria.net.server;

/**
 * Hears about clients coming and going. Methods run on the server's I/O thread: return quickly
 * (hand anything slow to another thread).
 */
public interface ServerListener {

  /** A client has logged in. */
  default void clientLoggedIn(ArServerClient client) {}

  /**
   * A connection has been closed, for the reason given (a client that never logged in is reported
   * too, for example one refused for a wrong password or dropped for garbage).
   */
  default void clientClosed(ArServerClient client, String reason) {}
}
