package org.jaria.sim;

/**
 * What the robots' ports did with their clients so far, summed over the robots (for {@code jaria
 * bench} and tests).
 *
 * @param sessions connections taken (each starts a session of its own)
 * @param refused connections closed because the robot had no room for them: the stalest when too
 *     many were in their handshake at once, and those whose handshake time ran out while the robot
 *     stayed taken
 * @param timedOut connections ended because the client did not finish the handshake in time or went
 *     silent
 * @param replaced silent clients that gave their robot up to a client that completed the handshake
 */
public record ServerCounters(long sessions, long refused, long timedOut, long replaced) {}
