package org.jaria.protocol.packets;

import java.util.Arrays;
import org.jaria.protocol.ArRobotPacket;

/**
 * GYROpac (0x98): a count of samples, then per sample a rate (0..1023, centred near 512; full scale
 * 300°/s) and a temperature byte.
 */
// Arrays are copied in and out and compared by content below.
@SuppressWarnings("ArrayRecordComponent")
public record GyroPacket(int[] rates, int[] temperatures) {

  /** Checks the arrays match and copies them. */
  public GyroPacket {
    if (rates.length != temperatures.length) {
      throw new IllegalArgumentException(
          rates.length + " rates but " + temperatures.length + " temperatures");
    }
    rates = rates.clone();
    temperatures = temperatures.clone();
  }

  @Override
  public int[] rates() {
    return rates.clone();
  }

  @Override
  public int[] temperatures() {
    return temperatures.clone();
  }

  /** Number of samples. */
  public int size() {
    return rates.length;
  }

  /** Rate of sample {@code i}. */
  public int rate(int i) {
    return rates[i];
  }

  /** Decodes {@code p}, or returns {@code null} if it is not a whole GYROpac. */
  public static GyroPacket decode(ArRobotPacket p) {
    if (p.getID() != PacketIds.GYRO) {
      return null;
    }
    p.resetRead();
    int n = p.bufToUByte();
    if (!p.isNextGood(3 * n)) {
      return null;
    }
    int[] r = new int[n];
    int[] t = new int[n];
    for (int i = 0; i < n; i++) {
      r[i] = p.bufToUByte2();
      t[i] = p.bufToUByte();
    }
    return p.isValid() ? new GyroPacket(r, t) : null;
  }

  /** Writes this packet into {@code p} and finalizes it. */
  public ArRobotPacket encode(ArRobotPacket p) {
    p.empty().setID(PacketIds.GYRO).uByteToBuf(rates.length);
    for (int i = 0; i < rates.length; i++) {
      p.uByte2ToBuf(rates[i]).uByteToBuf(temperatures[i]);
    }
    return p.finalizePacket();
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof GyroPacket g
        && Arrays.equals(rates, g.rates)
        && Arrays.equals(temperatures, g.temperatures);
  }

  @Override
  public int hashCode() {
    return 31 * Arrays.hashCode(rates) + Arrays.hashCode(temperatures);
  }

  @Override
  public String toString() {
    return "GyroPacket[rates="
        + Arrays.toString(rates)
        + ", temperatures="
        + Arrays.toString(temperatures)
        + "]";
  }
}
