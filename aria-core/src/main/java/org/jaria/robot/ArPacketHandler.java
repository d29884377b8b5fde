package org.jaria.robot;

import org.jaria.protocol.ArRobotPacket;

/**
 * Handles packets from the robot (ARIA's packet-handler functor). Handlers are asked in list order;
 * the first that returns {@code true} has taken the packet and the rest are not asked.
 */
@FunctionalInterface
public interface ArPacketHandler {

  /**
   * Looks at a packet; returns whether this handler took it. The packet is reused after the call:
   * copy it ({@link ArRobotPacket#copyFrom}) to keep it.
   */
  boolean handle(ArRobotPacket packet);
}
