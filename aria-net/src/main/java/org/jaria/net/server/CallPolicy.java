package org.jaria.net.server;

/**
 * How a server treats a client's requests of one data while they wait for the robot's cycle (set
 * with {@link ArServerBase#setCallPolicy}). ArNetworking has no such notion — its single server
 * loop applies requests one by one as they arrive — but a JAria server hands commands to the
 * robot's cycle through a bounded queue, and a client that sends faster than the cycle applies must
 * neither lose a stop nor fill the queue with positions of a joystick nobody holds any more.
 */
public enum CallPolicy {
  /**
   * Each request waits its turn; a client with too many requests waiting is refused as busy ({@link
   * ServerOptions#maxPendingCalls()}). The default.
   */
  QUEUED,
  /**
   * Only the newest request of this data from one client matters (a joystick's position: {@code
   * ratioDrive}): a newer one replaces the one still waiting, which counts as done. Never refused
   * as busy: one client has at most one waiting.
   */
  LATEST_WINS,
  /**
   * A safety command ({@code stop}, and anything that stops the robot): applied at the robot's next
   * cycle before everything else waiting, never refused as busy (repeats from one client collapse
   * to one), and nothing a client sent before it can leave the robot moving: requests of {@link
   * #LATEST_WINS} data sent before it are dropped, other earlier ones are applied before it, and
   * work of an earlier request that reaches the cycle after it is followed by the safety command
   * again.
   */
  SAFETY
}
