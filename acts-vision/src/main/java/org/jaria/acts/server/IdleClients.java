package org.jaria.acts.server;

import java.util.ArrayList;
import java.util.List;

/**
 * Which ACTS clients to disconnect, decided over plain values: clients idle past the timeout go;
 * and when the server is full, a newcomer takes the place of the client idle longest among those
 * that never asked for blobs or have been idle a while, so idle sockets can never keep the server
 * full. Only a request ({@code '0'}) or a reply taken is activity; garbage bytes are not.
 */
final class IdleClients {

  /**
   * What the decision needs to know about one client.
   *
   * @param lastActivityNanos when it last asked for blobs or took a whole reply (its connection
   *     time at first)
   * @param asked whether it ever asked for blobs
   */
  record View(long lastActivityNanos, boolean asked) {}

  private IdleClients() {}

  /** Indices of the clients idle for more than {@code timeoutNanos} at {@code now}. */
  static List<Integer> expired(List<View> clients, long now, long timeoutNanos) {
    List<Integer> out = new ArrayList<>();
    for (int i = 0; i < clients.size(); i++) {
      if (now - clients.get(i).lastActivityNanos() > timeoutNanos) {
        out.add(i);
      }
    }
    return out;
  }

  /**
   * The client to disconnect so a newcomer fits in a full server, or -1 if every client is busy:
   * the one idle longest among those that never asked for blobs or have been idle at least {@code
   * evictIdleNanos}.
   */
  static int toEvict(List<View> clients, long now, long evictIdleNanos) {
    int best = -1;
    long bestIdle = -1;
    for (int i = 0; i < clients.size(); i++) {
      View v = clients.get(i);
      long idle = now - v.lastActivityNanos();
      if ((!v.asked() || idle >= evictIdleNanos) && idle > bestIdle) {
        best = i;
        bestIdle = idle;
      }
    }
    return best;
  }
}
