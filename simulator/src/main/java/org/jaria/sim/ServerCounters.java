package org.jaria.sim;

/**
 * What the robots' ports did with their clients so far, summed over the robots (for {@code jaria
 * bench} and tests).
 *
 * @param sessions client sessions started
 * @param refused connections closed at once because the robot had a client (and one was waiting)
 * @param timedOut sessions ended because the client did not finish the handshake in time or went
 *     silent
 */
public record ServerCounters(long sessions, long refused, long timedOut) {}
