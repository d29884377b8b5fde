package org.jaria.laser;

import java.util.Arrays;

/**
 * The values of a scan telegram (answer 0xB0): a 16-bit count word (bits 0–9 the number of values,
 * bit 13 "partial scan", bits 11–12 the partial scan's index, bits 14–15 the unit: 00 cm, 01 mm, 10
 * 10 cm), then one 16-bit little-endian value per reading (distance in the low bits, reflectance in
 * the top 1–3 bits), then the status byte.
 *
 * @param distancesMm distances converted to mm
 * @param reflectance reflectance values, 0..7 (3 bits; fewer bits are shifted up)
 * @param unitMm mm per raw unit
 * @param partial whether this is one part of an interlaced scan
 * @param partIndex which part (0–3) of an interlaced scan
 * @param status the laser's status byte
 */
// The arrays are copied in and out.
@SuppressWarnings("ArrayRecordComponent")
public record LmsScanData(
    int[] distancesMm, int[] reflectance, int unitMm, boolean partial, int partIndex, int status) {

  /** Copies. */
  public LmsScanData {
    distancesMm = distancesMm.clone();
    reflectance = reflectance.clone();
  }

  @Override
  public int[] distancesMm() {
    return distancesMm.clone();
  }

  @Override
  public int[] reflectance() {
    return reflectance.clone();
  }

  /** Number of readings. */
  public int size() {
    return distancesMm.length;
  }

  /** Distance of reading {@code i}, mm. */
  public int distance(int i) {
    return distancesMm[i];
  }

  /** Bits of a raw value that hold the distance, for 1, 2 or 3 reflector bits. */
  public static int distanceMask(int reflectorBits) {
    return 0xffff >>> reflectorBits;
  }

  /**
   * Reads a scan telegram's data.
   *
   * @param reflectorBits how the laser was set up (1, 2 or 3)
   * @throws IllegalArgumentException if the telegram is not a scan or its length does not match its
   *     count
   */
  public static LmsScanData decode(LmsTelegram t, int reflectorBits) {
    if (t.command() != LmsCommands.SCAN) {
      throw new IllegalArgumentException(String.format("not a scan telegram: 0x%02x", t.command()));
    }
    if (t.dataLength() < 3) {
      throw new IllegalArgumentException("scan telegram too short: " + t.dataLength());
    }
    int word = t.u16(0);
    int count = word & 0x3ff;
    if (t.dataLength() != 2 + 2 * count + 1) {
      throw new IllegalArgumentException(
          "scan telegram of " + count + " values has " + t.dataLength() + " data bytes");
    }
    int unit =
        switch (word >>> 14) {
          case 0 -> 10;
          case 1 -> 1;
          case 2 -> 100;
          default -> throw new IllegalArgumentException("scan telegram with unknown unit bits 11");
        };
    int mask = distanceMask(reflectorBits);
    int[] d = new int[count];
    int[] refl = new int[count];
    for (int i = 0; i < count; i++) {
      int raw = t.u16(2 + 2 * i);
      d[i] = (raw & mask) * unit;
      refl[i] = (raw >>> (16 - reflectorBits)) << (3 - reflectorBits);
    }
    return new LmsScanData(
        d, refl, unit, (word & 0x2000) != 0, (word >>> 11) & 3, t.u8(t.dataLength() - 1));
  }

  /**
   * The scan telegram a laser sends for these readings (the emulator's side).
   *
   * @param rawDistances distances in the laser's unit, already clipped to the distance bits
   * @param reflectance reflectance 0..7 per reading (only the top {@code reflectorBits} are sent)
   * @param unitMm mm per unit: 1, 10 or 100
   */
  public static LmsTelegram encode(
      int[] rawDistances, int[] reflectance, int unitMm, int reflectorBits, int status) {
    int n = rawDistances.length;
    if (n > 0x3ff) {
      throw new IllegalArgumentException("an LMS scan holds at most 1023 values, not " + n);
    }
    int unitBits =
        switch (unitMm) {
          case 10 -> 0;
          case 1 -> 1;
          case 100 -> 2;
          default -> throw new IllegalArgumentException("no LMS unit of " + unitMm + " mm");
        };
    byte[] d = new byte[2 + 2 * n + 1];
    int word = n | unitBits << 14;
    d[0] = (byte) word;
    d[1] = (byte) (word >> 8);
    int mask = distanceMask(reflectorBits);
    for (int i = 0; i < n; i++) {
      int refl = (reflectance[i] >> (3 - reflectorBits)) << (16 - reflectorBits);
      int raw = Math.min(rawDistances[i], mask) | refl;
      d[2 + 2 * i] = (byte) raw;
      d[3 + 2 * i] = (byte) (raw >> 8);
    }
    d[d.length - 1] = (byte) status;
    return LmsTelegram.fromLaser(LmsCommands.SCAN, d);
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof LmsScanData s
        && Arrays.equals(s.distancesMm, distancesMm)
        && Arrays.equals(s.reflectance, reflectance)
        && s.unitMm == unitMm
        && s.partial == partial
        && s.partIndex == partIndex
        && s.status == status;
  }

  @Override
  public int hashCode() {
    return Arrays.hashCode(distancesMm) * 31 + Arrays.hashCode(reflectance);
  }

  @Override
  public String toString() {
    return "LmsScanData[" + distancesMm.length + " readings, " + unitMm + " mm units]";
  }
}
