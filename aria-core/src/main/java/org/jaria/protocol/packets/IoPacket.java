package org.jaria.protocol.packets;

import java.util.Arrays;
import org.jaria.protocol.ArRobotPacket;

/**
 * IOpac (0xF0): digital inputs (DIGIN, front bumpers, rear bumpers, IRs), digital outputs and
 * analog inputs (0..1023 each, the battery analog included). Each group is a count byte then the
 * values.
 */
// Arrays are copied in and out and compared by content below.
@SuppressWarnings("ArrayRecordComponent")
public record IoPacket(int[] digIn, int[] digOut, int[] analog) {

  /** Copies the arrays so the record stays immutable. */
  public IoPacket {
    digIn = digIn.clone();
    digOut = digOut.clone();
    analog = analog.clone();
  }

  @Override
  public int[] digIn() {
    return digIn.clone();
  }

  @Override
  public int[] digOut() {
    return digOut.clone();
  }

  @Override
  public int[] analog() {
    return analog.clone();
  }

  /** Decodes {@code p}, or returns {@code null} if it is not a whole IOpac. */
  public static IoPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.IO) {
      return null;
    }
    p.resetRead();
    int[] in = readBytes(p);
    int[] out = readBytes(p);
    int n = p.bufToUByte();
    if (!p.isNextGood(2 * n)) {
      return null;
    }
    int[] an = new int[n];
    for (int i = 0; i < n; i++) {
      an[i] = p.bufToUByte2();
    }
    return p.isValid() ? new IoPacket(in, out, an) : null;
  }

  private static int[] readBytes(ArRobotPacket p) {
    int n = Math.min(p.bufToUByte(), p.remaining());
    int[] v = new int[n];
    for (int i = 0; i < n; i++) {
      v[i] = p.bufToUByte();
    }
    return v;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.IO);
    p.uByteToBuf(digIn.length);
    for (int v : digIn) {
      p.uByteToBuf(v);
    }
    p.uByteToBuf(digOut.length);
    for (int v : digOut) {
      p.uByteToBuf(v);
    }
    p.uByteToBuf(analog.length);
    for (int v : analog) {
      p.uByte2ToBuf(v);
    }
    return p.finalizePacket();
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof IoPacket q
        && Arrays.equals(digIn, q.digIn)
        && Arrays.equals(digOut, q.digOut)
        && Arrays.equals(analog, q.analog);
  }

  @Override
  public int hashCode() {
    return 31 * (31 * Arrays.hashCode(digIn) + Arrays.hashCode(digOut)) + Arrays.hashCode(analog);
  }

  @Override
  public String toString() {
    return "IoPacket[digIn="
        + Arrays.toString(digIn)
        + ", digOut="
        + Arrays.toString(digOut)
        + ", analog="
        + Arrays.toString(analog)
        + "]";
  }
}
