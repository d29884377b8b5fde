package org.jaria.laser;

import java.util.Arrays;

/**
 * One telegram of a SICK LMS-200 family laser: {@code STX(0x02) ADDRESS LENGTH(2, little-endian)
 * COMMAND DATA... CRC(2, little-endian)}. LENGTH counts the command and data bytes; the CRC covers
 * every byte before it. The computer sends to address 0x00; the laser answers from 0x80. In a
 * laser's answer the last data byte is its status byte.
 *
 * @param address the address byte (0x00 to the laser, 0x80 from it)
 * @param command the command (to the laser) or answer (from it) code
 * @param data the bytes after the command, without the CRC
 */
// The array is copied in and out.
@SuppressWarnings("ArrayRecordComponent")
public record LmsTelegram(int address, int command, byte[] data) {

  /** Start byte of every telegram. */
  public static final int STX = 0x02;

  /** The laser's "received it" byte, sent before its answer telegram. */
  public static final int ACK = 0x06;

  /** The laser's "could not use it" byte. */
  public static final int NAK = 0x15;

  /** Address of telegrams to the laser. */
  public static final int TO_LASER = 0x00;

  /** Address of telegrams from the (first) laser. */
  public static final int FROM_LASER = 0x80;

  /** Longest LENGTH any LMS telegram has (a 0.25° interlaced scan is well below this). */
  public static final int MAX_LENGTH = 1024;

  /** Checks and copies. */
  public LmsTelegram {
    if (address < 0 || address > 0xff || command < 0 || command > 0xff) {
      throw new IllegalArgumentException("address and command are bytes");
    }
    if (data.length + 1 > MAX_LENGTH) {
      throw new IllegalArgumentException("telegram data too long: " + data.length);
    }
    data = data.clone();
  }

  /** A telegram to the laser. */
  public static LmsTelegram toLaser(int command, byte... data) {
    return new LmsTelegram(TO_LASER, command, data);
  }

  /** A telegram from the laser. */
  public static LmsTelegram fromLaser(int command, byte... data) {
    return new LmsTelegram(FROM_LASER, command, data);
  }

  @Override
  public byte[] data() {
    return data.clone();
  }

  /** Data byte {@code i} as 0..255. */
  public int u8(int i) {
    return data[i] & 0xff;
  }

  /** Data bytes {@code i}, {@code i+1} as a little-endian 0..65535. */
  public int u16(int i) {
    return (data[i] & 0xff) | (data[i + 1] & 0xff) << 8;
  }

  /** Number of data bytes. */
  public int dataLength() {
    return data.length;
  }

  /** The bytes on the wire, CRC included. */
  public byte[] encode() {
    int len = 1 + data.length;
    byte[] b = new byte[4 + len + 2];
    b[0] = STX;
    b[1] = (byte) address;
    b[2] = (byte) len;
    b[3] = (byte) (len >> 8);
    b[4] = (byte) command;
    System.arraycopy(data, 0, b, 5, data.length);
    int crc = crc(b, 0, b.length - 2);
    b[b.length - 2] = (byte) crc;
    b[b.length - 1] = (byte) (crc >> 8);
    return b;
  }

  /**
   * The LMS CRC-16 of {@code len} bytes: a shift register over the polynomial 0x8005 into which
   * each step XORs the current byte and the one before it (as the SICK telegram manual defines it).
   */
  public static int crc(byte[] b, int off, int len) {
    int crc = 0;
    int prev = 0;
    for (int i = off; i < off + len; i++) {
      int cur = b[i] & 0xff;
      if ((crc & 0x8000) != 0) {
        crc = ((crc & 0x7fff) << 1) ^ 0x8005;
      } else {
        crc = (crc << 1) & 0xffff;
      }
      crc ^= cur | prev << 8;
      prev = cur;
    }
    return crc & 0xffff;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof LmsTelegram t
        && t.address == address
        && t.command == command
        && Arrays.equals(t.data, data);
  }

  @Override
  public int hashCode() {
    return 31 * (31 * address + command) + Arrays.hashCode(data);
  }

  @Override
  public String toString() {
    return String.format(
        "LmsTelegram[addr 0x%02x, cmd 0x%02x, %d data bytes]", address, command, data.length);
  }
}
