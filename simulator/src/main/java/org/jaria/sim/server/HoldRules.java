package org.jaria.sim.server;

/**
 * Who may hold a simulated robot, decided over plain values (see {@link RobotClients} for the whole
 * rule): a holder that has gone silent can be replaced, and when a robot has as many connections in
 * its handshake as it keeps, the stalest of them makes room for a newcomer.
 */
public final class HoldRules {

  private HoldRules() {}

  /**
   * Whether the holder of a robot may be replaced by a client that has just completed the
   * handshake: only a network client, and only once it has sent no valid packet for {@code
   * silentNanos}. ARIA sends at least a PULSE every half second, so a program that is running never
   * loses its robot this way.
   *
   * @param lastPacketNanos when the holder last sent a whole, valid packet
   */
  public static boolean replaceable(
      ClientKind kind, long lastPacketNanos, long now, long silentNanos) {
    return kind.isNetwork() && now - lastPacketNanos >= silentNanos;
  }

  /**
   * Which of {@code n} connections in their handshake makes room for a newcomer: the oldest of
   * those that have not sent one valid packet (squatters, and garbage senders: garbage is not a
   * packet), else the one whose last packet is oldest. A client doing its handshake sends a packet
   * per round trip, so it is the last to go.
   *
   * @param connectedNanos when each connection was made
   * @param lastPacketNanos when each last sent a valid packet
   * @param sentPacket whether each has sent one at all
   * @return the index of the connection to close (-1 if {@code n} is 0)
   */
  public static int stalest(
      long[] connectedNanos, long[] lastPacketNanos, boolean[] sentPacket, int n) {
    int best = -1;
    for (int i = 0; i < n; i++) {
      if (best < 0 || staler(i, best, connectedNanos, lastPacketNanos, sentPacket)) {
        best = i;
      }
    }
    return best;
  }

  private static boolean staler(
      int i, int j, long[] connectedNanos, long[] lastPacketNanos, boolean[] sentPacket) {
    if (sentPacket[i] != sentPacket[j]) {
      return !sentPacket[i];
    }
    return sentPacket[i]
        ? lastPacketNanos[i] - lastPacketNanos[j] < 0
        : connectedNanos[i] - connectedNanos[j] < 0;
  }
}
