package org.jaria.net.server;

import java.util.List;

/**
 * Whether a new connection may wait to log in, given those already waiting: the decision as a plain
 * function of values, so the rules can be tested without sockets.
 *
 * <ul>
 *   <li>An address has at most {@code perAddress} connections waiting: its newest replaces its
 *       oldest, so sockets that never log in cannot keep that address's real users out (they log in
 *       within milliseconds; squatters must keep replacing each other).
 *   <li>Below the global ceiling, everybody else is accepted.
 *   <li>At the ceiling, a <em>privileged</em> newcomer — from the loopback address, or from an
 *       address that has logged in before — replaces the oldest waiting connection of an
 *       unprivileged address (or, if all are privileged, the oldest of all); anyone else is
 *       refused.
 * </ul>
 */
final class PendingAdmission {

  private PendingAdmission() {}

  /** A connection waiting to log in. */
  record Waiting(String address, long connectedNanos, boolean privileged) {}

  /** What to do with the newcomer: accept it, after closing {@code replaced} (-1: none), or not. */
  record Decision(boolean accept, int replaced) {
    static final Decision ACCEPT = new Decision(true, -1);
    static final Decision REFUSE = new Decision(false, -1);

    static Decision replacing(int index) {
      return new Decision(true, index);
    }
  }

  /**
   * The decision for a newcomer from {@code address}.
   *
   * @param waiting the connections waiting to log in now
   * @param privileged whether the newcomer is from the loopback or an address that logged in before
   * @param perAddress most waiting from one address
   * @param total most waiting over all addresses
   */
  static Decision admit(
      List<Waiting> waiting, String address, boolean privileged, int perAddress, int total) {
    int sameCount = 0;
    int sameOldest = -1;
    int unprivilegedOldest = -1;
    int oldest = -1;
    for (int i = 0; i < waiting.size(); i++) {
      Waiting w = waiting.get(i);
      if (w.address().equals(address)) {
        sameCount++;
        sameOldest = older(waiting, sameOldest, i);
      }
      if (!w.privileged()) {
        unprivilegedOldest = older(waiting, unprivilegedOldest, i);
      }
      oldest = older(waiting, oldest, i);
    }
    if (sameCount >= perAddress) {
      return Decision.replacing(sameOldest);
    }
    if (waiting.size() < total) {
      return Decision.ACCEPT;
    }
    if (!privileged) {
      return Decision.REFUSE;
    }
    return Decision.replacing(unprivilegedOldest >= 0 ? unprivilegedOldest : oldest);
  }

  private static int older(List<Waiting> w, int best, int i) {
    return best < 0 || w.get(i).connectedNanos() - w.get(best).connectedNanos() < 0 ? i : best;
  }
}
