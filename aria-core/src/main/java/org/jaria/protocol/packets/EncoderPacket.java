package org.jaria.protocol.packets;

import org.jaria.protocol.ArRobotPacket;

/**
 * ENCODERpac (0x90): raw encoder counts of the left and right wheels. Each 32-bit count is sent as
 * its low 16 bits then its high 16 bits, both little-endian.
 */
public record EncoderPacket(int left, int right) {

  /** Decodes {@code p}, or returns {@code null} if it is not a whole ENCODERpac. */
  public static EncoderPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.ENCODER) {
      return null;
    }
    p.resetRead();
    int left = p.bufToUByte2() | (p.bufToUByte2() << 16);
    int right = p.bufToUByte2() | (p.bufToUByte2() << 16);
    return p.isValid() ? new EncoderPacket(left, right) : null;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.ENCODER);
    p.uByte2ToBuf(left & 0xFFFF).uByte2ToBuf(left >>> 16);
    p.uByte2ToBuf(right & 0xFFFF).uByte2ToBuf(right >>> 16);
    return p.finalizePacket();
  }
}
