package org.jaria.sim;

import java.nio.file.Path;
import java.util.Set;

/**
 * How a world's robot ports treat their clients: how long a client may take for the handshake and
 * stay silent, which commands are ignored, and where client map loads may come from. The defaults
 * are safe when the ports are reachable from other machines; see "Hostile clients and safe
 * defaults" in docs/simulator.md.
 *
 * @param handshakeTimeoutMillis a network client that has not sent OPEN this long after connecting
 *     (or after a CLOSE) is disconnected, ms (default 2000). Until it has completed the handshake
 *     (SYNC0..SYNC2) a connection never holds the robot, so this only bounds what a squatter costs.
 * @param clientTimeoutMillis a network client of an open robot that sends no packet for this long
 *     is disconnected and the robot freed, ms (default 10000; 0 never). The watchdog stops the
 *     robot long before.
 * @param ignoredCommands command numbers every robot ignores (MobileSim's {@code --ignore-command})
 * @param mapFolder the folder client map loads (SIM_CTRL 1 and 2) are confined to; {@code null}
 *     means the working directory, for clients on this machine only
 * @param maxMapBytes the largest map file a client may load (default 64 MiB)
 * @param remoteExit whether SIM_EXIT from a client on another machine ends the simulator (default
 *     false: only clients on the loopback may end it)
 * @param refusalLogMillis at most one log line per robot this often about refused connections, ms
 *     (default 10000); the rest are counted
 * @param replaceSilentMillis a network client holding a robot that has sent no valid packet for
 *     this long gives it up to the next client that completes the handshake, ms (default 2000, the
 *     watchdog's time; ARIA sends a packet at least every half second)
 */
public record SimServerOptions(
    int handshakeTimeoutMillis,
    int clientTimeoutMillis,
    Set<Integer> ignoredCommands,
    Path mapFolder,
    long maxMapBytes,
    boolean remoteExit,
    int refusalLogMillis,
    int replaceSilentMillis) {

  /** The defaults. */
  public static final SimServerOptions DEFAULTS =
      new SimServerOptions(2000, 10_000, Set.of(), null, 64L << 20, false, 10_000, 2000);

  /** Checks the values. */
  public SimServerOptions {
    if (handshakeTimeoutMillis < 1) {
      throw new IllegalArgumentException(
          "the handshake timeout must be at least 1 ms, was " + handshakeTimeoutMillis);
    }
    if (clientTimeoutMillis < 0) {
      throw new IllegalArgumentException(
          "the client timeout must be 0 (never) or more ms, was " + clientTimeoutMillis);
    }
    for (int c : ignoredCommands) {
      if (c < 0 || c > 255) {
        throw new IllegalArgumentException("command numbers are 0..255, got " + c);
      }
    }
    ignoredCommands = Set.copyOf(ignoredCommands);
    if (maxMapBytes < 1) {
      throw new IllegalArgumentException("the map size limit must be positive, was " + maxMapBytes);
    }
    if (refusalLogMillis < 0) {
      throw new IllegalArgumentException(
          "the refusal log interval must be 0 or more ms, was " + refusalLogMillis);
    }
    if (replaceSilentMillis < 1) {
      throw new IllegalArgumentException(
          "the time after which a silent client can be replaced must be at least 1 ms, was "
              + replaceSilentMillis);
    }
  }

  /** These options with other timeouts, ms. */
  public SimServerOptions withTimeouts(int handshakeMillis, int clientMillis) {
    return new SimServerOptions(
        handshakeMillis,
        clientMillis,
        ignoredCommands,
        mapFolder,
        maxMapBytes,
        remoteExit,
        refusalLogMillis,
        replaceSilentMillis);
  }

  /** These options ignoring {@code commands} (numbers 0..255). */
  public SimServerOptions withIgnoredCommands(Set<Integer> commands) {
    return new SimServerOptions(
        handshakeTimeoutMillis,
        clientTimeoutMillis,
        commands,
        mapFolder,
        maxMapBytes,
        remoteExit,
        refusalLogMillis,
        replaceSilentMillis);
  }

  /**
   * These options with client map loads confined to {@code folder} (for clients anywhere), files of
   * at most {@code maxBytes}.
   */
  public SimServerOptions withMapFolder(Path folder, long maxBytes) {
    return new SimServerOptions(
        handshakeTimeoutMillis,
        clientTimeoutMillis,
        ignoredCommands,
        folder,
        maxBytes,
        remoteExit,
        refusalLogMillis,
        replaceSilentMillis);
  }

  /** These options letting clients on other machines end the simulator with SIM_EXIT. */
  public SimServerOptions withRemoteExit(boolean allowed) {
    return new SimServerOptions(
        handshakeTimeoutMillis,
        clientTimeoutMillis,
        ignoredCommands,
        mapFolder,
        maxMapBytes,
        allowed,
        refusalLogMillis,
        replaceSilentMillis);
  }

  /**
   * These options with holders silent for {@code millis} replaceable by the next client that
   * completes the handshake.
   */
  public SimServerOptions withReplaceSilentMillis(int millis) {
    return new SimServerOptions(
        handshakeTimeoutMillis,
        clientTimeoutMillis,
        ignoredCommands,
        mapFolder,
        maxMapBytes,
        remoteExit,
        refusalLogMillis,
        millis);
  }
}
