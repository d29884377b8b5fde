package org.jaria.site.samples;

import java.util.concurrent.atomic.AtomicLong;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.packets.EncoderPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.robot.ArListPos;
import org.jaria.robot.ArRobot;

/** Building command packets and handling server packets (the ARCOS guide). */
public final class ProtocolSample {

  private ProtocolSample() {}

  /** The bytes of ENABLE 1, as text. */
  public static String enableMotors() {
    // tag::build[]
    ArRobotPacket p = new ArRobotPacket();
    CommandCodec.comInt(p, ArCommands.ENABLE.getNumber(), 1); // fills and adds the checksum
    String bytes = p.toHexString(); // "FA FB 06 04 3B 01 00 05 3B"
    // end::build[]
    return bytes;
  }

  /** Asks for encoder packets and keeps the last left-wheel count; returns the holder. */
  public static AtomicLong watchEncoders(ArRobot robot) {
    AtomicLong left = new AtomicLong();
    // tag::handler[]
    robot.addPacketHandler(
        packet -> {
          if (packet.getID() != PacketIds.ENCODER) {
            return false; // not ours: let the next handler look at it
          }
          EncoderPacket encoders = EncoderPacket.decode(packet);
          if (encoders != null) {
            left.set(encoders.left());
          }
          return true; // taken: handlers after this one do not see it
        },
        ArListPos.FIRST); // before ArRobot's own handlers, which would take it first
    robot.requestEncoderPackets(); // ENCODER 2: one 0x90 packet every cycle from now on
    // end::handler[]
    return left;
  }
}
