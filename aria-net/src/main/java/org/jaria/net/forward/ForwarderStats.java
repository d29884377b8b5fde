package org.jaria.net.forward;

/**
 * What a video forwarder has done so far.
 *
 * @param connected whether it is connected to its video server now
 * @param connects successful connections (the first one and every reconnection)
 * @param failedConnects connection attempts that failed
 * @param lost connections lost or dropped (the server left, broke the protocol or stalled)
 * @param stalls connections dropped because the server stopped answering
 * @param requests frame requests sent to the server
 * @param frames frames received and passed on
 * @param dropped packets dropped: not a frame or a size, or a frame nobody asked for
 * @param served frames (and sizes) sent to the forwarder's own clients
 */
public record ForwarderStats(
    boolean connected,
    long connects,
    long failedConnects,
    long lost,
    long stalls,
    long requests,
    long frames,
    long dropped,
    long served) {}
