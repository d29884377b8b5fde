package org.jaria.sim.server;

/**
 * Where a robot's client is: in this program, on this machine over TCP, or on another machine. The
 * simulator trusts them differently: only network clients are timed out, and only clients on this
 * machine may end the simulator or load maps from its working directory.
 */
public enum ClientKind {
  /** An in-memory connection from a test or tool in the same program. */
  IN_MEMORY,
  /** A TCP client on the loopback address (this machine). */
  LOOPBACK_TCP,
  /** A TCP client from another address. */
  REMOTE_TCP;

  /** The kind of a TCP client whose address is {@code remote}. */
  public static ClientKind ofTcpPeer(java.net.SocketAddress remote) {
    return remote instanceof java.net.InetSocketAddress a
            && a.getAddress() != null
            && a.getAddress().isLoopbackAddress()
        ? LOOPBACK_TCP
        : REMOTE_TCP;
  }

  /** Whether the client is on this machine. */
  public boolean isLocal() {
    return this != REMOTE_TCP;
  }

  /** Whether the client comes over the network (and is timed out when silent). */
  public boolean isNetwork() {
    return this != IN_MEMORY;
  }
}
