package org.jaria.web.mcap;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Map;

/**
 * A growable little-endian byte buffer with MCAP's record framing: opcode, uint64 length, content.
 * Strings are a uint32 byte length and UTF-8; maps a uint32 byte length and their entries.
 */
final class Records {

  private byte[] buf;
  private int n;

  Records(int capacity) {
    buf = new byte[Math.max(capacity, 64)];
  }

  int size() {
    return n;
  }

  void reset() {
    n = 0;
  }

  byte[] array() {
    return buf;
  }

  byte[] toArray() {
    return Arrays.copyOf(buf, n);
  }

  private void ensure(int more) {
    if (n + more > buf.length) {
      buf = Arrays.copyOf(buf, Math.max(buf.length * 2, n + more));
    }
  }

  Records u8(int v) {
    ensure(1);
    buf[n++] = (byte) v;
    return this;
  }

  Records u16(int v) {
    ensure(2);
    ByteBuffer.wrap(buf, n, 2).order(ByteOrder.LITTLE_ENDIAN).putShort((short) v);
    n += 2;
    return this;
  }

  Records u32(long v) {
    ensure(4);
    ByteBuffer.wrap(buf, n, 4).order(ByteOrder.LITTLE_ENDIAN).putInt((int) v);
    n += 4;
    return this;
  }

  Records u64(long v) {
    ensure(8);
    ByteBuffer.wrap(buf, n, 8).order(ByteOrder.LITTLE_ENDIAN).putLong(v);
    n += 8;
    return this;
  }

  Records bytes(byte[] b, int off, int len) {
    ensure(len);
    System.arraycopy(b, off, buf, n, len);
    n += len;
    return this;
  }

  Records bytes(byte[] b) {
    return bytes(b, 0, b.length);
  }

  Records string(String s) {
    byte[] b = s.getBytes(StandardCharsets.UTF_8);
    return u32(b.length).bytes(b);
  }

  Records stringMap(Map<String, String> m) {
    int lengthAt = n;
    u32(0);
    for (var e : m.entrySet()) {
      string(e.getKey()).string(e.getValue());
    }
    patch32(lengthAt, n - lengthAt - 4);
    return this;
  }

  /** Starts a record; returns where its length goes, for {@link #endRecord}. */
  int beginRecord(int opcode) {
    u8(opcode);
    int at = n;
    u64(0);
    return at;
  }

  /** Writes the record's length; returns the whole record's size (opcode and length included). */
  long endRecord(int lengthAt) {
    long content = (long) n - lengthAt - 8;
    ByteBuffer.wrap(buf, lengthAt, 8).order(ByteOrder.LITTLE_ENDIAN).putLong(content);
    return 1 + 8 + content;
  }

  void patch32(int at, long v) {
    ByteBuffer.wrap(buf, at, 4).order(ByteOrder.LITTLE_ENDIAN).putInt((int) v);
  }
}
