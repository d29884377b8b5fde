package org.jaria.ptz;

/**
 * One VISCA message a Sony camera sends back (header {@code 90} from camera 1 … terminator {@code
 * FF}), sorted by what it says. Immutable.
 */
public final class ViscaReply {

  private final Kind kind;
  private final byte[] bytes;

  private ViscaReply(Kind kind, byte[] bytes) {
    this.kind = kind;
    this.bytes = bytes;
  }

  /** What the message is. */
  public Kind kind() {
    return kind;
  }

  /** The whole message (a copy). */
  public byte[] bytes() {
    return bytes.clone();
  }

  /** Its length in bytes, terminator included. */
  public int length() {
    return bytes.length;
  }

  /** What a reply says. */
  public enum Kind {
    /** {@code 90 4y FF}: the command was taken into socket y. */
    ACK,
    /** {@code 90 5y FF}: the command in socket y is done. */
    COMPLETION,
    /** {@code 90 50 … FF} with data: the answer to an inquiry. */
    ANSWER,
    /**
     * {@code 90 6y ee FF}: error ee (02 syntax, 03 buffer full, 04 cancelled, 41 not executable).
     */
    ERROR,
    /** {@code 88 …}: a broadcast (interface clear, address set) back from the end of the chain. */
    BROADCAST,
    /** Anything else. */
    OTHER
  }

  /** Sorts one whole message (ending {@code FF}). */
  public static ViscaReply of(byte[] m) {
    int n = m.length;
    int h = n > 0 ? m[0] & 0xFF : 0;
    int b1 = n > 1 ? m[1] & 0xFF : 0;
    Kind k;
    if (h == 0x88) {
      k = Kind.BROADCAST;
    } else if ((h & 0x8F) != 0x80 || n < 3) {
      k = Kind.OTHER;
    } else if (b1 == 0x50 && n > 3) {
      k = Kind.ANSWER;
    } else if ((b1 & 0xF0) == 0x40 && n == 3) {
      k = Kind.ACK;
    } else if ((b1 & 0xF0) == 0x50 && n == 3) {
      k = Kind.COMPLETION;
    } else if ((b1 & 0xF0) == 0x60 && n == 4) {
      k = Kind.ERROR;
    } else {
      k = Kind.OTHER;
    }
    return new ViscaReply(k, m.clone());
  }

  /** The error code of an {@link Kind#ERROR} (−1 otherwise). */
  public int errorCode() {
    return kind == Kind.ERROR ? bytes[2] & 0xFF : -1;
  }

  /**
   * The {@code i}-th 16-bit value of an answer, four nibbles each after {@code 90 50}, as a signed
   * number (pan and tilt are signed; zoom is 0..0x3FF).
   */
  public int value(int i) {
    int at = 2 + 4 * i;
    if (kind != Kind.ANSWER || at + 4 > bytes.length - 1) {
      throw new IllegalStateException("no value " + i + " in " + kind + " of " + bytes.length);
    }
    int v = 0;
    for (int k = at; k < at + 4; k++) {
      v = (v << 4) | (bytes[k] & 0x0F);
    }
    return (short) v;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof ViscaReply r && r.kind == kind && java.util.Arrays.equals(r.bytes, bytes);
  }

  @Override
  public int hashCode() {
    return kind.hashCode() * 31 + java.util.Arrays.hashCode(bytes);
  }

  @Override
  public String toString() {
    return kind + " " + java.util.HexFormat.ofDelimiter(" ").formatHex(bytes);
  }
}
