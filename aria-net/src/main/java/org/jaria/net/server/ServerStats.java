package org.jaria.net.server;

import java.util.concurrent.atomic.LongAdder;

/** Counters of what happened to a server's connections, for logs, tests and benchmarks. */
public final class ServerStats {

  final LongAdder accepted = new LongAdder();
  final LongAdder refusedFull = new LongAdder();
  final LongAdder loginFailed = new LongAdder();
  final LongAdder loginTimeouts = new LongAdder();
  final LongAdder malformed = new LongAdder();
  final LongAdder droppedSlow = new LongAdder();
  final LongAdder droppedIdle = new LongAdder();
  final LongAdder requests = new LongAdder();
  final LongAdder busy = new LongAdder();
  final LongAdder updatesQueued = new LongAdder();
  final LongAdder loginThrottled = new LongAdder();
  final LongAdder refusedPending = new LongAdder();
  final LongAdder replacedPending = new LongAdder();
  final LongAdder loginBusy = new LongAdder();
  final LongAdder requestErrors = new LongAdder();
  final LongAdder udpDropped = new LongAdder();
  final LongAdder superseded = new LongAdder();
  final LongAdder safetyReasserted = new LongAdder();

  ServerStats() {}

  /** Connections accepted (not counting those refused because the server was full). */
  public long getAccepted() {
    return accepted.sum();
  }

  /** Connections refused because the server had its maximum of clients. */
  public long getRefusedFull() {
    return refusedFull.sum();
  }

  /** Logins refused (wrong user or password, wrong protocol version). */
  public long getLoginFailed() {
    return loginFailed.sum();
  }

  /** Connections closed because they did not log in in time. */
  public long getLoginTimeouts() {
    return loginTimeouts.sum();
  }

  /** Connections closed for a malformed frame or a message out of place. */
  public long getMalformed() {
    return malformed.sum();
  }

  /** Clients dropped for reading too slowly (queue overflow or stall). */
  public long getDroppedSlow() {
    return droppedSlow.sum();
  }

  /** Clients dropped for saying nothing for too long. */
  public long getDroppedIdle() {
    return droppedIdle.sum();
  }

  /** Requests handled (or refused as busy). */
  public long getRequests() {
    return requests.sum();
  }

  /** Requests refused because queues were full. */
  public long getBusy() {
    return busy.sum();
  }

  /** Logins refused without checking because the address failed too often. */
  public long getLoginThrottled() {
    return loginThrottled.sum();
  }

  /** Connections closed at once because too many had not logged in yet. */
  public long getRefusedPending() {
    return refusedPending.sum();
  }

  /**
   * Connections waiting to log in that were closed to make room for a newer one (from the same
   * address, or from the loopback or a known address when the server had its most waiting).
   */
  public long getReplacedPending() {
    return replacedPending.sum();
  }

  /** Logins refused without checking because too many passwords were being checked. */
  public long getLoginBusy() {
    return loginBusy.sum();
  }

  /** Requests that failed (bad arguments, handler errors, busy). */
  public long getRequestErrors() {
    return requestErrors.sum();
  }

  /** UDP datagrams ignored (not a packet, or from an unknown sender). */
  public long getUdpDropped() {
    return udpDropped.sum();
  }

  /**
   * Requests replaced by a newer one of the same data from the same client before the robot's cycle
   * applied them (latest-wins data such as ratioDrive), or made moot by a stop.
   */
  public long getSuperseded() {
    return superseded.sum();
  }

  /** Times a stop was applied again because work asked for before it reached the cycle after it. */
  public long getSafetyReasserted() {
    return safetyReasserted.sum();
  }

  /** Updates queued for requests at an interval. */
  public long getUpdatesQueued() {
    return updatesQueued.sum();
  }

  @Override
  public String toString() {
    return String.format(
        java.util.Locale.ROOT,
        "accepted %d, refused full %d, login failed %d, login timeouts %d, malformed %d,"
            + " dropped slow %d, dropped idle %d, requests %d, busy %d, updates %d",
        getAccepted(),
        getRefusedFull(),
        getLoginFailed(),
        getLoginTimeouts(),
        getMalformed(),
        getDroppedSlow(),
        getDroppedIdle(),
        getRequests(),
        getBusy(),
        getUpdatesQueued());
  }
}
