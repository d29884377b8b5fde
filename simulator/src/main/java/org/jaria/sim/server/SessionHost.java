package org.jaria.sim.server;

import org.jaria.clock.Clock;
import org.jaria.sim.world.WorldGeometry;

/**
 * What a robot's ARCOS session needs from the world it lives in: time, world-wide settings and the
 * simulator meta-operations (map loading, exit, statistics). Implemented by the world; called on
 * the world thread only.
 */
public interface SessionHost {

  /** The simulated clock. */
  Clock clock();

  /** Everything solid in the world (for the laser scans sent with the SIPs). */
  WorldGeometry world();

  /** SIP cycle, ms. */
  int sipCycleMillis();

  /** Watchdog time, ms (0 = no watchdog). */
  int watchdogMillis();

  /** Whether the watchdog only warns instead of stopping the robot. */
  boolean watchdogWarnOnly();

  /**
   * Records a command the robot did not carry out; the first of each number and reason is logged
   * (once for the whole simulator).
   */
  void ignoredCommand(int command, IgnoredCommand.Reason reason, String robotName);

  /**
   * SIM_CTRL load map: loads {@code path} (relative to the map folder, off the world thread) and,
   * once loaded, tells every client (SIM_MAP_CHANGED); a map that cannot be loaded is answered to
   * the asking robot's client only, with status -1.
   */
  void loadMapRequested(String path, int robotIndex);

  /** Which commands are carried out for which clients. */
  CommandPolicy commandPolicy();

  /**
   * A network client has this long from connecting (or CLOSE) to OPEN, ms; a connection that has
   * not completed the handshake by then is closed.
   */
  int handshakeTimeoutMillis();

  /** A network client of an open robot silent this long is disconnected, ms (0 never). */
  int clientTimeoutMillis();

  /**
   * A network client holding a robot that has sent no valid packet this long gives the robot up to
   * the next client that completes the handshake, ms.
   */
  int replaceSilentMillis();

  /** SIM_EXIT: a client asks the simulator to exit with {@code code}. */
  void exitRequested(int code, String robotName);

  /** SIM_CTRL ghost mode: the robot stops being seen or touched by others. */
  void ghostRequested(int robotIndex);

  /** Whether a map is loaded (SIMSTAT flag bit 0). */
  boolean haveMap();

  /** Simulated milliseconds per world tick (SIMSTAT SimInterval). */
  int simIntervalMillis();

  /** Real milliseconds a tick should take (SIMSTAT RealInterval; 0 in lockstep). */
  int realIntervalMillis();

  /** Real milliseconds the last tick took (SIMSTAT LastInterval; 0 in lockstep). */
  int lastIntervalMillis();
}
