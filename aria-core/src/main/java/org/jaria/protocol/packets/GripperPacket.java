package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * GRIPPERpac (0xE0).
 *
 * @param hasGripper 0 none, 1 Pioneer gripper, 2 PeopleBot gripper
 * @param gripState GRIP_STATE bits (see {@link GripState})
 * @param graspTime grasp time
 */
public record GripperPacket(int hasGripper, int gripState, int graspTime) {

  /** Decodes {@code p}, or returns {@code null} if it is not a whole GRIPPERpac. */
  public static GripperPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.GRIPPER) {
      return null;
    }
    p.resetRead();
    GripperPacket g = new GripperPacket(p.bufToUByte(), p.bufToUByte(), p.bufToUByte());
    return p.isValid() ? g : null;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.GRIPPER);
    return p.uByteToBuf(hasGripper).uByteToBuf(gripState).uByteToBuf(graspTime).finalizePacket();
  }
}
