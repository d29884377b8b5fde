package org.jaria.protocol.packets;

import java.util.Arrays;
import org.jaria.protocol.ArRobotPacket;

/**
 * SERAUXpac: bytes read from an auxiliary serial port (0xB0 AUX1, 0xB8 AUX2, 0xC8 AUX3).
 *
 * @param port 1, 2 or 3
 * @param data the bytes, in arrival order
 */
// Arrays are copied in and out and compared by content below.
@SuppressWarnings("ArrayRecordComponent")
public record SerAuxPacket(int port, byte[] data) {

  /** Checks the port and copies the data. */
  public SerAuxPacket {
    idFor(port);
    data = data.clone();
  }

  @Override
  public byte[] data() {
    return data.clone();
  }

  /** The packet ID for AUX port {@code port} (1..3). */
  public static int idFor(int port) {
    return switch (port) {
      case 1 -> PacketIds.SERAUX1;
      case 2 -> PacketIds.SERAUX2;
      case 3 -> PacketIds.SERAUX3;
      default -> throw new IllegalArgumentException("AUX port " + port + " not in 1..3");
    };
  }

  /** Decodes {@code p}, or returns {@code null} if it is not a SERAUX packet. */
  public static SerAuxPacket decode(ArRobotPacket p) {
    int port =
        switch (p.getID()) {
          case PacketIds.SERAUX1 -> 1;
          case PacketIds.SERAUX2 -> 2;
          case PacketIds.SERAUX3 -> 3;
          default -> 0;
        };
    if (port == 0) {
      return null;
    }
    p.resetRead();
    byte[] d = new byte[p.getDataLength()];
    p.bufToData(d, 0, d.length);
    return new SerAuxPacket(port, d);
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(idFor(port));
    return p.dataToBuf(data, 0, data.length).finalizePacket();
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof SerAuxPacket s && s.port == port && Arrays.equals(s.data, data);
  }

  @Override
  public int hashCode() {
    return 31 * port + Arrays.hashCode(data);
  }

  @Override
  public String toString() {
    return "SerAuxPacket[port=" + port + ", data=" + Arrays.toString(data) + "]";
  }
}
