package org.jaria.protocol;

/**
 * Builds client command packets and reads their arguments back (the robot side of the same rules).
 * Both directions live here so that the encoder and the decoder cannot drift apart.
 */
public final class CommandCodec {

  /** Largest magnitude an integer argument can carry. */
  public static final int MAX_INT_ARG = 0xFFFF;

  private CommandCodec() {}

  /** Fills {@code p} with a command that has no argument. */
  public static ArRobotPacket com(ArRobotPacket p, int command) {
    return p.empty().setID(command).finalizePacket();
  }

  /**
   * Fills {@code p} with a command and an integer argument: 0x3B and the value for positive values
   * and zero, 0x1B and the absolute value for negative ones.
   *
   * @throws IllegalArgumentException if {@code |value| > 65535}
   */
  public static ArRobotPacket comInt(ArRobotPacket p, int command, int value) {
    if (value > MAX_INT_ARG || value < -MAX_INT_ARG) {
      throw new IllegalArgumentException(
          "command "
              + command
              + ": argument "
              + value
              + " does not fit in 16 bits; ARCOS integers are -65535..65535");
    }
    p.empty().setID(command);
    if (value >= 0) {
      p.uByteToBuf(ArgKind.INT_ARG).uByte2ToBuf(value);
    } else {
      p.uByteToBuf(ArgKind.NEG_INT_ARG).uByte2ToBuf(-value);
    }
    return p.finalizePacket();
  }

  /** Fills {@code p} with a two-byte command (VEL2, DIGOUT): one integer, high byte first. */
  public static ArRobotPacket com2Bytes(ArRobotPacket p, int command, int high, int low) {
    return comInt(p, command, ((high & 0xFF) << 8) | (low & 0xFF));
  }

  /**
   * Fills {@code p} with a string command: 0x2B, a length byte, the characters and (as the
   * reference client does) a NUL.
   */
  public static ArRobotPacket comStr(ArRobotPacket p, int command, String s) {
    if (s.length() > 199) {
      throw new IllegalArgumentException(
          "command " + command + ": string of " + s.length() + " chars; ARCOS takes at most 199");
    }
    p.empty().setID(command).uByteToBuf(ArgKind.STR_ARG).uByteToBuf(s.length());
    return p.strToBuf(s).finalizePacket();
  }

  /** Fills {@code p} with a string command carrying exactly {@code n} bytes of {@code s}. */
  public static ArRobotPacket comStrN(ArRobotPacket p, int command, String s, int n) {
    if (n < 0 || n > 199) {
      throw new IllegalArgumentException("command " + command + ": length " + n + " not in 0..199");
    }
    p.empty().setID(command).uByteToBuf(ArgKind.STR_ARG).uByteToBuf(n);
    return p.strNToBuf(s, n).finalizePacket();
  }

  /** Fills {@code p} with a string command whose characters are raw bytes (e.g. SAY's pairs). */
  public static ArRobotPacket comDataN(
      ArRobotPacket p, int command, byte[] data, int off, int len) {
    if (len < 0 || len > 199) {
      throw new IllegalArgumentException(
          "command " + command + ": length " + len + " not in 0..199");
    }
    p.empty().setID(command).uByteToBuf(ArgKind.STR_ARG).uByteToBuf(len);
    return p.dataToBuf(data, off, len).finalizePacket();
  }

  // ---------------------------------------------------------------- robot side

  /** Whether the packet carries any argument bytes. */
  public static boolean hasArg(ArRobotPacket p) {
    return p.getDataLength() > 0;
  }

  /**
   * Reads an integer argument from the start of the payload. The sign comes from the type byte
   * (0x1B negative); any other type byte is read as positive, as ARCOS does.
   *
   * @param missing the value to return when the packet has no argument
   */
  public static int readIntArg(ArRobotPacket p, int missing) {
    p.resetRead();
    if (p.getDataLength() < 3) {
      return missing;
    }
    int type = p.bufToUByte();
    int magnitude = p.bufToUByte2();
    return type == ArgKind.NEG_INT_ARG ? -magnitude : magnitude;
  }

  /**
   * Reads a string argument (type byte, length byte, characters). A length beyond the packet is cut
   * to the bytes present.
   */
  public static String readStringArg(ArRobotPacket p) {
    byte[] raw = readDataArg(p);
    StringBuilder sb = new StringBuilder(raw.length);
    for (byte b : raw) {
      if (b == 0) {
        break;
      }
      sb.append((char) (b & 0xFF));
    }
    return sb.toString();
  }

  /** Reads a string argument's raw bytes (for SAY and POLLING, whose characters are numbers). */
  public static byte[] readDataArg(ArRobotPacket p) {
    p.resetRead();
    if (p.getDataLength() < 2) {
      return new byte[0];
    }
    p.bufToUByte(); // type byte
    int len = Math.min(p.bufToUByte(), p.remaining());
    byte[] out = new byte[len];
    p.bufToData(out, 0, len);
    return out;
  }
}
