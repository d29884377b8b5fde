package org.jaria.net.client;

/**
 * Hears a client connect and disconnect. Runs on the client's threads: a JavaFX program must hand
 * the work to its application thread ({@code Platform.runLater}).
 */
public interface ConnectionListener {

  /** Logged in; subscriptions have been sent again. */
  default void connected(ArClientBase client) {}

  /** The connection ended (by {@link ArClientBase#disconnect()}, the server or the network). */
  default void disconnected(ArClientBase client, String reason) {}
}
