package org.jaria.sim.server;

/**
 * Decides when a repeated event (a refused connection) gets a log line: the first at once, then at
 * most one per interval, saying how many were not logged in between. Not thread-safe; one per
 * robot, used on the world thread.
 */
public final class LogRateLimit {

  private final long intervalNanos;
  private boolean loggedOnce;
  private long lastLoggedNanos;
  private long unlogged;

  /** At most one line per {@code intervalNanos} (0: every event is logged). */
  public LogRateLimit(long intervalNanos) {
    this.intervalNanos = intervalNanos;
  }

  /**
   * Counts one event at {@code now}; returns -1 if it should not be logged, else how many events
   * before it went unlogged (to say in the line).
   */
  public long record(long now) {
    if (loggedOnce && now - lastLoggedNanos < intervalNanos) {
      unlogged++;
      return -1;
    }
    long n = unlogged;
    loggedOnce = true;
    lastLoggedNanos = now;
    unlogged = 0;
    return n;
  }
}
