package org.jaria.protocol.packets;

import java.util.Locale;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.ArgKind;
import org.jaria.protocol.CommandCodec;
import org.jaria.protocol.Hex;

/**
 * Describes ARCOS packets in words, for protocol debugging ({@code ./jaria packets}). The same
 * bytes mean different things in the two directions (ID 32 is VEL2 from a client but CONFIGpac from
 * a robot), so the caller says which way a packet went, or lets {@link Direction#AUTO} guess from
 * the ID and length.
 */
public final class PacketFormatter {

  /** Which way a packet travelled. */
  public enum Direction {
    /** From the client (a command). */
    CLIENT,
    /** From the robot (a SIP or another server packet). */
    ROBOT,
    /** Guess: server packet IDs with payloads that fit them are robot packets. */
    AUTO
  }

  private PacketFormatter() {}

  /** One line describing {@code p}. */
  public static String describe(ArRobotPacket p, Direction dir) {
    Direction d = dir == Direction.AUTO ? guess(p) : dir;
    String body = d == Direction.ROBOT ? describeServer(p) : describeCommand(p);
    return (d == Direction.ROBOT ? "robot  " : "client ") + body;
  }

  private static Direction guess(ArRobotPacket p) {
    int id = p.getID();
    int len = p.getDataLength();
    if (PacketIds.isStandardSip(id) && len >= 21) {
      return Direction.ROBOT;
    }
    if (id == PacketIds.CONFIG && len > 20) {
      return Direction.ROBOT;
    }
    if (id >= 0x60 && ArCommands.fromNumber(id) == null) {
      return Direction.ROBOT;
    }
    return Direction.CLIENT;
  }

  /** Describes a client command: its name and argument. */
  public static String describeCommand(ArRobotPacket p) {
    int id = p.getID();
    ArCommands c = ArCommands.fromNumber(id);
    String name = c == null ? "UNKNOWN(" + id + ")" : c.name() + "(" + id + ")";
    if (p.getDataLength() == 0) {
      return name;
    }
    p.resetRead();
    int type = p.bufToUByte();
    p.resetRead();
    if (type == ArgKind.STR_ARG) {
      byte[] data = CommandCodec.readDataArg(p);
      StringBuilder sb = new StringBuilder(name).append(" str[").append(data.length).append("] ");
      boolean printable = true;
      for (byte b : data) {
        printable &= b >= 32 && b < 127;
      }
      if (printable) {
        sb.append('"')
            .append(new String(data, java.nio.charset.StandardCharsets.ISO_8859_1))
            .append('"');
      } else {
        sb.append(Hex.format(data));
      }
      return sb.toString();
    }
    if (type == ArgKind.INT_ARG || type == ArgKind.NEG_INT_ARG) {
      int v = CommandCodec.readIntArg(p, 0);
      if (c != null && c.getArgKind() == ArgKind.TWO_BYTES) {
        return String.format(Locale.ROOT, "%s high %d low %d", name, (byte) (v >> 8), (byte) v);
      }
      return name + " " + v;
    }
    byte[] rest = new byte[p.getDataLength()];
    p.bufToData(rest, 0, rest.length);
    return name + " data " + Hex.format(rest);
  }

  /** Describes a server packet: a SIP's fields, CONFIGpac's values, and so on. */
  public static String describeServer(ArRobotPacket p) {
    int id = p.getID();
    if (PacketIds.isStandardSip(id)) {
      StandardSip s = new StandardSip();
      if (!s.decode(p)) {
        return "SIP (malformed: too short)";
      }
      StringBuilder sb = new StringBuilder();
      sb.append(
          String.format(
              Locale.ROOT,
              "SIP %s x=%d y=%d th=%d lvel=%d rvel=%d batt=%.1fV stall=0x%04X control=%d flags=0x%04X"
                  + " compass=%d sonar=%d",
              s.isMoving() ? "moving" : "stopped",
              s.getXPos(),
              s.getYPos(),
              s.getThPos(),
              s.getLeftVel(),
              s.getRightVel(),
              s.getBattery() / 10.0,
              s.getStallAndBumpers(),
              s.getControl(),
              s.getFlags(),
              s.getCompass(),
              s.getSonarCount()));
      for (int i = 0; i < s.getSonarCount(); i++) {
        sb.append(i == 0 ? " [" : " ")
            .append(s.getSonarNumber(i))
            .append(':')
            .append(s.getSonarRange(i));
        if (i == s.getSonarCount() - 1) {
          sb.append(']');
        }
      }
      if (s.getOptionalCount() > 0) {
        sb.append(" +").append(s.getOptionalCount()).append(" tail fields");
      }
      return sb.toString();
    }
    Object decoded =
        switch (id) {
          case PacketIds.CONFIG -> ArConfigPacket.decode(p);
          case PacketIds.ENCODER -> EncoderPacket.decode(p);
          case PacketIds.IO -> IoPacket.decode(p);
          case PacketIds.JOYSTICK -> JoystickPacket.decode(p);
          case PacketIds.GRIPPER -> GripperPacket.decode(p);
          case PacketIds.GYRO -> GyroPacket.decode(p);
          case PacketIds.TCM2 -> Tcm2Packet.decode(p);
          case PacketIds.SERAUX1, PacketIds.SERAUX2, PacketIds.SERAUX3 -> SerAuxPacket.decode(p);
          case PacketIds.SIMSTAT -> SimStatPacket.decode(p);
          default -> null;
        };
    if (decoded != null) {
      return decoded.toString();
    }
    if (id <= 2 && p.getDataLength() == 0) {
      return "SYNC" + id + " echo";
    }
    if (id == 2) {
      p.resetRead();
      return "SYNC2 echo name=\""
          + p.bufToString()
          + "\" type=\""
          + p.bufToString()
          + "\" subtype=\""
          + p.bufToString()
          + "\"";
    }
    byte[] rest = new byte[p.getDataLength()];
    p.resetRead();
    p.bufToData(rest, 0, rest.length);
    return String.format(Locale.ROOT, "packet 0x%02X data %s", id, Hex.format(rest));
  }
}
