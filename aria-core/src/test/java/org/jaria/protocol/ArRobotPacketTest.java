package org.jaria.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ArRobotPacketTest {

  private static String hex(ArRobotPacket p) {
    return p.toHexString();
  }

  @Test
  void syncPacketsMatchTheSpec() {
    ArRobotPacket p = new ArRobotPacket();
    assertEquals("FA FB 03 00 00 00", hex(CommandCodec.com(p, 0)));
    assertEquals("FA FB 03 01 00 01", hex(CommandCodec.com(p, 1)));
    assertEquals("FA FB 03 02 00 02", hex(CommandCodec.com(p, 2)));
  }

  @Test
  void enableAndNegativeVelocityMatchTheSpec() {
    ArRobotPacket p = new ArRobotPacket();
    assertEquals("FA FB 06 04 3B 01 00 05 3B", hex(CommandCodec.comInt(p, 4, 1)));
    assertEquals("FA FB 06 0B 1B C8 00 D3 1B", hex(CommandCodec.comInt(p, 11, -200)));
  }

  @Test
  void thesisDigoutExampleHasAValidChecksum() {
    int[] dec = {250, 251, 6, 30, 27, 25, 9, 55, 36};
    byte[] frame = new byte[dec.length];
    for (int i = 0; i < dec.length; i++) {
      frame[i] = (byte) dec[i];
    }
    ArRobotPacket p = new ArRobotPacket().load(frame, 0, frame.length);
    assertTrue(p.verifyCheckSum());
    assertEquals(30, p.getID());
  }

  @Test
  void checksumOfOddLengthXorsTheLastByte() {
    byte[] b = {0x01, 0x02, 0x03};
    assertEquals(0x0102 ^ 0x03, ArRobotPacket.checksum(b, 0, 3));
    byte[] e = {(byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF};
    assertEquals(0xFFFE, ArRobotPacket.checksum(e, 0, 4));
  }

  @Test
  void everyFieldTypeRoundTrips() {
    ArRobotPacket p = new ArRobotPacket(0x42);
    p.byteToBuf(-5).uByteToBuf(250).byte2ToBuf(-1234).uByte2ToBuf(60000);
    p.byte4ToBuf(-123456789).uByte4ToBuf(4000000000L).strToBuf("hello").strNToBuf("ab", 4);
    p.finalizePacket();
    assertTrue(p.verifyCheckSum());
    assertEquals(0x42, p.getID());
    assertEquals(p.getLength() - 6, p.getDataLength());
    assertEquals(-5, p.bufToByte());
    assertEquals(250, p.bufToUByte());
    assertEquals(-1234, p.bufToByte2());
    assertEquals(60000, p.bufToUByte2());
    assertEquals(-123456789, p.bufToByte4());
    assertEquals(4000000000L, p.bufToUByte4());
    assertEquals("hello", p.bufToString());
    assertEquals("ab", p.bufToStringN(4));
    assertEquals(0, p.remaining());
    assertTrue(p.isValid());
  }

  @Test
  void readingPastTheEndReturnsZeroAndMarksInvalid() {
    ArRobotPacket p = new ArRobotPacket(7).uByteToBuf(9).finalizePacket();
    assertEquals(9, p.bufToUByte());
    assertTrue(p.isValid());
    assertEquals(0, p.bufToUByte2());
    assertFalse(p.isValid());
    p.resetRead();
    assertTrue(p.isValid());
  }

  @Test
  void overfullPacketIsRefusedWithAClearMessage() {
    ArRobotPacket p = new ArRobotPacket(1);
    for (int i = 0; i < ArRobotPacket.MAX_DATA_LENGTH; i++) {
      p.uByteToBuf(i);
    }
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> p.uByteToBuf(1));
    assertTrue(e.getMessage().contains("at most"), e.getMessage());
    assertEquals(ArRobotPacket.MAX_LENGTH, p.finalizePacket().getLength());
    assertTrue(p.verifyCheckSum());
  }

  @Test
  void corruptedByteFailsVerification() {
    ArRobotPacket p = CommandCodec.comInt(new ArRobotPacket(), 11, 300);
    byte[] b = p.toByteArray();
    b[5] ^= 0x10;
    assertFalse(new ArRobotPacket().load(b, 0, b.length).verifyCheckSum());
  }
}
