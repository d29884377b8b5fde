package org.jaria.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class ArNetPacketTest {

  private static byte[] bytes(int... v) {
    byte[] b = new byte[v.length];
    for (int i = 0; i < v.length; i++) {
      b[i] = (byte) v[i];
    }
    return b;
  }

  @Test
  void anEmptyPacketIsSyncLengthCommandAndChecksum() {
    // TCP_ONLY (5) with no body, as ARIA 2.9.1's clients send it.
    assertArrayEquals(
        bytes(0x0f, 0x0c, 0x08, 0x00, 0x05, 0x00, 0x00, 0x05), new ArNetPacket(5).toWire());
  }

  @Test
  void valuesAreLittleEndianAndStringsEndWithZero() {
    ArNetPacket p = new ArNetPacket(300);
    p.byte2ToBuf(-2).byte4ToBuf(0x01020304).strToBuf("ab").doubleToBuf(0.5);
    byte[] w = p.toWire();
    assertEquals(0x2c, w[4] & 0xff);
    assertEquals(0x01, w[5] & 0xff);
    assertArrayEquals(
        bytes(0xfe, 0xff, 0x04, 0x03, 0x02, 0x01, 'a', 'b', 0, '0', '.', '5', 0), p.toByteArray());
    ArNetPacket r = ArNetPacket.fromWire(w, 0, w.length);
    assertEquals(300, r.getCommand());
    assertEquals(-2, r.bufToByte2());
    assertEquals(0x01020304, r.bufToByte4());
    assertEquals("ab", r.bufToStr());
    assertEquals(0.5, r.bufToDouble());
  }

  @Test
  void doublesAreWrittenAsCsPercentG() {
    assertEquals("100", ArNetPacket.formatDouble(100));
    assertEquals("-12.5", ArNetPacket.formatDouble(-12.5));
    assertEquals("3.14159", ArNetPacket.formatDouble(Math.PI));
    assertEquals("1e+06", ArNetPacket.formatDouble(1e6));
    assertEquals("0.0001", ArNetPacket.formatDouble(1e-4));
    assertEquals("1e-05", ArNetPacket.formatDouble(1e-5));
    assertEquals("INF", ArNetPacket.formatDouble(Double.POSITIVE_INFINITY));
    assertEquals("-INF", ArNetPacket.formatDouble(Double.NEGATIVE_INFINITY));
  }

  @Test
  void hostileBodiesAreRefusedNotReadAsZero() {
    ArNetPacket noZero = ArNetPacket.wrap(bytes('a', 'b'));
    assertThrows(ArNetPacketException.class, noZero::bufToStr);
    ArNetPacket shortInt = ArNetPacket.wrap(bytes(1, 2));
    assertThrows(ArNetPacketException.class, shortInt::bufToByte4);
    ArNetPacket text = ArNetPacket.wrap(bytes('x', 'y', 0));
    assertThrows(ArNetPacketException.class, text::bufToDouble);
    ArNetPacket nan = ArNetPacket.wrap(bytes('n', 'a', 'n', 0));
    assertEquals(Double.NaN, nan.bufToDouble());
    ArNetPacket huge = ArNetPacket.wrap(bytes(0xff, 0xff, 0xff, 0x7f));
    assertThrows(ArNetPacketException.class, huge::bufToArray);
  }

  @Test
  void aBadChecksumOrSyncIsRefused() {
    byte[] w = new ArNetPacket(5).toWire();
    w[7] ^= 1;
    assertThrows(ArNetPacketException.class, () -> ArNetPacket.fromWire(w, 0, w.length));
    byte[] v = new ArNetPacket(5).toWire();
    v[0] = 0x0e;
    assertThrows(ArNetPacketException.class, () -> ArNetPacket.fromWire(v, 0, v.length));
  }

  @Test
  void aPacketHoldsAtMost32000BytesOnTheWire() {
    ArNetPacket p = new ArNetPacket(256);
    p.dataToBuf(new byte[ArNetPacket.MAX_DATA_LENGTH]);
    assertEquals(32000, p.toWire().length);
    assertThrows(ArNetPacketException.class, () -> p.byteToBuf(1));
  }
}
