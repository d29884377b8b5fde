package org.jaria.protocol;

import java.nio.charset.StandardCharsets;

/**
 * One ARCOS packet: {@code 0xFA 0xFB COUNT ID payload... CHK_HI CHK_LO}.
 *
 * <p>The same class builds packets (the {@code ...ToBuf} methods, then {@link #finalizePacket()})
 * and reads them (the {@code bufTo...} methods), with ARIA's method names so that packet handlers
 * written for ARIA port line by line. Integers in the payload are little-endian; the checksum is
 * big-endian.
 *
 * <p>A packet object owns a fixed 207-byte buffer and is meant to be reused: nothing here allocates
 * except the methods that return a {@code String}. Reading past the end of the data does not throw;
 * it returns 0 and clears {@link #isValid()}, so a decoder can read a whole structure and check
 * once at the end.
 *
 * <p>Not thread-safe: one packet belongs to one thread at a time.
 */
public final class ArRobotPacket {

  /** First header byte. */
  public static final int HEADER1 = 0xFA;

  /** Second header byte. */
  public static final int HEADER2 = 0xFB;

  /** Largest whole packet in bytes, header and checksum included. */
  public static final int MAX_LENGTH = 207;

  /** Largest COUNT byte a robot accepts (ID + payload + checksum). */
  public static final int MAX_COUNT = MAX_LENGTH - 3;

  /** Smallest COUNT byte: an ID and the two checksum bytes. */
  public static final int MIN_COUNT = 3;

  /** Bytes before the payload: two header bytes, COUNT and ID. */
  public static final int HEADER_LENGTH = 4;

  /** Bytes after the payload: the checksum. */
  public static final int FOOTER_LENGTH = 2;

  /** Largest payload (bytes after the ID, before the checksum). */
  public static final int MAX_DATA_LENGTH = MAX_LENGTH - HEADER_LENGTH - FOOTER_LENGTH;

  private final byte[] buf = new byte[MAX_LENGTH];

  /** Write position while building; total length (incl. checksum) once finalized or loaded. */
  private int length;

  private boolean finalized;
  private int readPos;
  private boolean valid = true;

  /** An empty packet with ID 0, ready for {@code ...ToBuf} calls. */
  public ArRobotPacket() {
    empty();
  }

  /** An empty packet with the given ID, ready for {@code ...ToBuf} calls. */
  public ArRobotPacket(int id) {
    empty();
    setID(id);
  }

  // ---------------------------------------------------------------- building

  /** Clears the packet for building a new one; keeps the ID. */
  public ArRobotPacket empty() {
    buf[0] = (byte) HEADER1;
    buf[1] = (byte) HEADER2;
    length = HEADER_LENGTH;
    finalized = false;
    valid = true;
    readPos = HEADER_LENGTH;
    return this;
  }

  /** Sets the packet ID (the command number for client packets, the type for server packets). */
  public ArRobotPacket setID(int id) {
    buf[3] = (byte) id;
    return this;
  }

  /** Appends a signed byte. */
  public ArRobotPacket byteToBuf(int value) {
    ensureRoom(1);
    buf[length++] = (byte) value;
    return this;
  }

  /** Appends an unsigned byte (0..255). */
  public ArRobotPacket uByteToBuf(int value) {
    return byteToBuf(value);
  }

  /** Appends a 16-bit integer, little-endian (signed or unsigned: the low 16 bits are written). */
  public ArRobotPacket byte2ToBuf(int value) {
    ensureRoom(2);
    buf[length++] = (byte) value;
    buf[length++] = (byte) (value >> 8);
    return this;
  }

  /** Appends an unsigned 16-bit integer, little-endian. */
  public ArRobotPacket uByte2ToBuf(int value) {
    return byte2ToBuf(value);
  }

  /** Appends a 32-bit integer, little-endian. */
  public ArRobotPacket byte4ToBuf(int value) {
    ensureRoom(4);
    buf[length++] = (byte) value;
    buf[length++] = (byte) (value >> 8);
    buf[length++] = (byte) (value >> 16);
    buf[length++] = (byte) (value >> 24);
    return this;
  }

  /** Appends an unsigned 32-bit integer (given as a long), little-endian. */
  public ArRobotPacket uByte4ToBuf(long value) {
    return byte4ToBuf((int) value);
  }

  /** Appends the characters of {@code s} followed by a NUL terminator. */
  public ArRobotPacket strToBuf(String s) {
    byte[] bytes = s.getBytes(StandardCharsets.ISO_8859_1);
    ensureRoom(bytes.length + 1);
    System.arraycopy(bytes, 0, buf, length, bytes.length);
    length += bytes.length;
    buf[length++] = 0;
    return this;
  }

  /**
   * Appends exactly {@code n} bytes: the characters of {@code s}, cut or padded with NULs (ARIA's
   * {@code strNToBuf}).
   */
  public ArRobotPacket strNToBuf(String s, int n) {
    byte[] bytes = s.getBytes(StandardCharsets.ISO_8859_1);
    ensureRoom(n);
    int copy = Math.min(n, bytes.length);
    System.arraycopy(bytes, 0, buf, length, copy);
    for (int i = copy; i < n; i++) {
      buf[length + i] = 0;
    }
    length += n;
    return this;
  }

  /** Appends raw bytes. */
  public ArRobotPacket dataToBuf(byte[] data, int off, int len) {
    ensureRoom(len);
    System.arraycopy(data, off, buf, length, len);
    length += len;
    return this;
  }

  /**
   * Writes the COUNT byte and the checksum. After this the packet can be sent ({@link #getBuf()},
   * {@link #getLength()}) and read back.
   */
  public ArRobotPacket finalizePacket() {
    if (!finalized) {
      buf[2] = (byte) (length - 3 + FOOTER_LENGTH);
      int c = checksum(buf, 3, length - 3);
      buf[length++] = (byte) (c >> 8);
      buf[length++] = (byte) c;
      finalized = true;
    }
    readPos = HEADER_LENGTH;
    valid = true;
    return this;
  }

  private void ensureRoom(int n) {
    if (finalized) {
      throw new IllegalStateException(
          "packet already finalized: call empty() before building a new one");
    }
    if (length + n > MAX_LENGTH - FOOTER_LENGTH) {
      throw new IllegalArgumentException(
          "ARCOS packets carry at most "
              + (MAX_DATA_LENGTH + 1)
              + " bytes after the header; this one would need "
              + (length + n - 3)
              + ". Split the data over several packets.");
    }
  }

  // ---------------------------------------------------------------- loading

  /**
   * Loads a complete frame (header to checksum) received from the wire. The frame is not verified;
   * see {@link #verifyCheckSum()}.
   *
   * @throws IllegalArgumentException if {@code len} is not a possible packet length
   */
  public ArRobotPacket load(byte[] src, int off, int len) {
    if (len < HEADER_LENGTH + FOOTER_LENGTH - 1 || len > MAX_LENGTH) {
      throw new IllegalArgumentException("not an ARCOS frame length: " + len);
    }
    System.arraycopy(src, off, buf, 0, len);
    length = len;
    finalized = true;
    readPos = HEADER_LENGTH;
    valid = true;
    return this;
  }

  /** Copies another packet into this one (for handlers that keep a packet beyond the call). */
  public ArRobotPacket copyFrom(ArRobotPacket other) {
    return load(other.buf, 0, other.length);
  }

  // ---------------------------------------------------------------- reading

  /** The packet ID (command number or server packet type), 0..255. */
  public int getID() {
    return buf[3] & 0xFF;
  }

  /** Total bytes of the packet, header and (once finalized) checksum included. */
  public int getLength() {
    return length;
  }

  /** The payload length: bytes after the ID and before the checksum. */
  public int getDataLength() {
    return finalized ? length - HEADER_LENGTH - FOOTER_LENGTH : length - HEADER_LENGTH;
  }

  /** How many payload bytes have been read so far. */
  public int getDataReadLength() {
    return readPos - HEADER_LENGTH;
  }

  /** Payload bytes not yet read. */
  public int remaining() {
    return getDataLength() - getDataReadLength();
  }

  /** Whether {@code n} more bytes can be read. */
  public boolean isNextGood(int n) {
    return n <= remaining();
  }

  /** False once a read has run past the end of the payload. */
  public boolean isValid() {
    return valid;
  }

  /** Moves the read position back to the first payload byte and clears the read error. */
  public void resetRead() {
    readPos = HEADER_LENGTH;
    valid = true;
  }

  /** Skips {@code n} payload bytes. */
  public void skip(int n) {
    if (take(n)) {
      readPos += n;
    }
  }

  private boolean take(int n) {
    if (readPos + n > HEADER_LENGTH + getDataLength()) {
      valid = false;
      return false;
    }
    return true;
  }

  /** Reads a signed byte (0 past the end). */
  public int bufToByte() {
    if (!take(1)) {
      return 0;
    }
    return buf[readPos++];
  }

  /** Reads an unsigned byte. */
  public int bufToUByte() {
    if (!take(1)) {
      return 0;
    }
    return buf[readPos++] & 0xFF;
  }

  /** Reads a signed little-endian 16-bit integer. */
  public int bufToByte2() {
    if (!take(2)) {
      return 0;
    }
    int v = (buf[readPos] & 0xFF) | (buf[readPos + 1] << 8);
    readPos += 2;
    return (short) v;
  }

  /** Reads an unsigned little-endian 16-bit integer. */
  public int bufToUByte2() {
    if (!take(2)) {
      return 0;
    }
    int v = (buf[readPos] & 0xFF) | ((buf[readPos + 1] & 0xFF) << 8);
    readPos += 2;
    return v;
  }

  /** Reads a signed little-endian 32-bit integer. */
  public int bufToByte4() {
    if (!take(4)) {
      return 0;
    }
    int v =
        (buf[readPos] & 0xFF)
            | ((buf[readPos + 1] & 0xFF) << 8)
            | ((buf[readPos + 2] & 0xFF) << 16)
            | ((buf[readPos + 3] & 0xFF) << 24);
    readPos += 4;
    return v;
  }

  /** Reads an unsigned little-endian 32-bit integer. */
  public long bufToUByte4() {
    return bufToByte4() & 0xFFFFFFFFL;
  }

  /**
   * Reads a NUL-terminated string; the terminator is consumed. A string that runs to the end of the
   * payload without a terminator is returned as it is.
   */
  public String bufToString() {
    int end = HEADER_LENGTH + getDataLength();
    int start = readPos;
    int i = start;
    while (i < end && buf[i] != 0) {
      i++;
    }
    String s = new String(buf, start, i - start, StandardCharsets.ISO_8859_1);
    readPos = Math.min(end, i + 1);
    return s;
  }

  /** Reads exactly {@code n} bytes as a string, stopping the string at the first NUL. */
  public String bufToStringN(int n) {
    if (!take(n)) {
      return "";
    }
    int len = 0;
    while (len < n && buf[readPos + len] != 0) {
      len++;
    }
    String s = new String(buf, readPos, len, StandardCharsets.ISO_8859_1);
    readPos += n;
    return s;
  }

  /** Copies {@code len} payload bytes into {@code dst}. */
  public void bufToData(byte[] dst, int off, int len) {
    if (take(len)) {
      System.arraycopy(buf, readPos, dst, off, len);
      readPos += len;
    }
  }

  // ---------------------------------------------------------------- checksum

  /** The checksum of this packet's ID and payload, as the robot computes it. */
  public int calcCheckSum() {
    int n = (finalized ? length - FOOTER_LENGTH : length) - 3;
    return checksum(buf, 3, n);
  }

  /** Whether the checksum bytes at the end of a finalized or loaded packet are right. */
  public boolean verifyCheckSum() {
    if (!finalized || length < HEADER_LENGTH + FOOTER_LENGTH - 1) {
      return false;
    }
    int stored = ((buf[length - 2] & 0xFF) << 8) | (buf[length - 1] & 0xFF);
    return stored == calcCheckSum();
  }

  /**
   * The ARCOS checksum of {@code n} bytes starting at {@code off}: sum of big-endian byte pairs
   * modulo 2^16, with a final odd byte XORed in.
   */
  public static int checksum(byte[] b, int off, int n) {
    int c = 0;
    int i = off;
    while (n > 1) {
      c += ((b[i] & 0xFF) << 8) | (b[i + 1] & 0xFF);
      c &= 0xFFFF;
      i += 2;
      n -= 2;
    }
    if (n > 0) {
      c ^= b[i] & 0xFF;
    }
    return c;
  }

  /**
   * The internal buffer (header first). Valid up to {@link #getLength()}; it is the packet's own
   * array, so write it out before the packet is reused.
   */
  public byte[] getBuf() {
    return buf;
  }

  /** A copy of the packet's bytes. */
  public byte[] toByteArray() {
    byte[] out = new byte[length];
    System.arraycopy(buf, 0, out, 0, length);
    return out;
  }

  /**
   * The packet's bytes as upper-case hex pairs separated by spaces, e.g. {@code FA FB 03 00 00 00}.
   */
  public String toHexString() {
    return Hex.format(buf, 0, length);
  }

  @Override
  public String toString() {
    return "ArRobotPacket[id=0x" + Integer.toHexString(getID()) + ", " + toHexString() + "]";
  }
}
