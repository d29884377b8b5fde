package org.jaria.net.forward;

/**
 * When a video forwarder asks its video server for the next frame, gives up on it, and tries it
 * again: plain decisions over times in milliseconds, so that they can be tested as values.
 *
 * <p>The request rule is ArNetworking's ({@code ArHybridForwarderVideo}): ask again once the last
 * frame is older than the request interval (100 ms by default) and no request is outstanding, or
 * when a request has gone unanswered for 3 s. JAria adds the rest: a server that has left a request
 * unanswered for the stall time is dropped and connected to again, with a wait that doubles after
 * each failed attempt.
 */
public final class ForwardingRules {

  /** ArNetworking's default interval between a frame and the next request (ms). */
  public static final long DEFAULT_REQUEST_INTERVAL_MS = 100;

  /** After this long without an answer the request is sent again, as ArNetworking does (ms). */
  public static final long REREQUEST_MS = 3000;

  /** A server that has answered nothing for this long while asked is dropped (ms). */
  public static final long STALL_MS = 10_000;

  /** First wait before connecting again (ms); it doubles up to {@link #MAX_RECONNECT_MS}. */
  public static final long FIRST_RECONNECT_MS = 500;

  /** Longest wait between two connection attempts (ms). */
  public static final long MAX_RECONNECT_MS = 8000;

  private ForwardingRules() {}

  /**
   * Whether to ask for the next frame now.
   *
   * @param sinceFrameMs time since the last frame came (or since connecting)
   * @param requestOut whether a request is outstanding
   * @param sinceRequestMs time since the last request was sent
   * @param intervalMs the request interval
   */
  public static boolean shouldRequest(
      long sinceFrameMs, boolean requestOut, long sinceRequestMs, long intervalMs) {
    return requestOut ? sinceRequestMs > REREQUEST_MS : sinceFrameMs > intervalMs;
  }

  /**
   * Whether the server has stalled: a request is outstanding and nothing useful has come for {@link
   * #STALL_MS}.
   */
  public static boolean isStalled(boolean requestOut, long sinceFrameMs) {
    return requestOut && sinceFrameMs > STALL_MS;
  }

  /** How long to wait before the next connection attempt after {@code failures} failed ones. */
  public static long reconnectDelayMs(int failures) {
    if (failures <= 0) {
      return 0;
    }
    int doublings = Math.min(failures - 1, 30);
    return Math.min(MAX_RECONNECT_MS, FIRST_RECONNECT_MS << doublings);
  }
}
