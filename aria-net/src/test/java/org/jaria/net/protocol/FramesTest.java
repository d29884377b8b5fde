package org.jaria.net.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.HexFormat;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.Points;
import org.junit.jupiter.api.Test;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;

/**
 * The bytes on the wire, exactly as PROTOCOL.md documents them: if one of these changes, clients
 * written in other languages break, and the protocol version must change with it.
 */
class FramesTest {

  private static byte[] hex(String s) {
    return HexFormat.of().parseHex(s.replace(" ", ""));
  }

  private static String hex(byte[] b) {
    return HexFormat.ofDelimiter(" ").formatHex(b);
  }

  private static byte[] enc(org.jaria.net.NetEncodable v) {
    ArNetPacket p = new ArNetPacket();
    v.write(p);
    return p.toByteArray();
  }

  @Test
  void protocolConstantsAreThoseDocumented() {
    assertEquals("JARIA-NET", Protocol.MAGIC);
    assertEquals(1, Protocol.VERSION);
    assertEquals(7272, Protocol.DEFAULT_PORT);
    int[] codes = {1, 2, 3, 4, 5, 6, 7, 11, 12, 13, 14, 15, 16, 17, 18, 19};
    Kind[] kinds = Kind.values();
    assertEquals(codes.length, kinds.length);
    for (int i = 0; i < codes.length; i++) {
      assertEquals(codes[i], kinds[i].code(), kinds[i].name());
      assertEquals(kinds[i], Kind.fromCode(codes[i]));
    }
    assertEquals(null, Kind.fromCode(0));
    assertEquals(null, Kind.fromCode(-1));
    assertEquals(null, Kind.fromCode(1L << 40));
    assertEquals(NetError.BAD_LOGIN, NetError.fromCode(21));
    assertEquals(null, NetError.fromCode(99));
  }

  @Test
  void helloGoldenBytes() {
    byte[] f = Frames.frame(Kind.HELLO, Protocol.MAGIC, Protocol.VERSION, "t", "u");
    assertEquals(
        "00 00 00 10 01 a9 4a 41 52 49 41 2d 4e 45 54 01 a1 74 a1 75", hex(f), "HELLO frame");
  }

  @Test
  void pingAndCallGoldenBytes() {
    assertEquals("00 00 00 04 06 cd 01 2c", hex(Frames.frame(Kind.PING, 300)));
    // CALL request 7 of data 3 with arguments 1000.0 and -2.5 (doubles are always float 64).
    assertEquals(
        "00 00 00 15 03 07 03 cb 40 8f 40 00 00 00 00 00 cb c0 04 00 00 00 00 00 00",
        hex(Frames.frame(Kind.CALL, 7, 3, 1000.0, -2.5)));
    assertEquals("00 00 00 01 07", hex(Frames.frame(Kind.BYE)));
  }

  @Test
  void updateHeaderGoldenBytes() {
    ByteBuffer b = ByteBuffer.allocate(Frames.MAX_HEADER_BYTES);
    Frames.putHeader(b, Kind.UPDATE, 5, 70000, true, 3);
    byte[] got = new byte[b.remaining()];
    b.get(got);
    // length 11: kind 15, data id 5, version 70000 (uint 32), final true, then 3 payload bytes.
    assertEquals("00 00 00 0b 0f 05 ce 00 01 11 70 c3", hex(got));
    Frames.putHeader(b, Kind.RESPONSE, 1, 2, false, 61440);
    assertEquals(4 + 61440, b.getInt(0), "the length covers the header's values and the part");
    assertEquals((byte) 0xc2, b.get(b.limit() - 1), "not the final part");
  }

  @Test
  void headerEqualsAFrameOfTheSameValues() {
    byte[] payload = ArNetPacket.of("abc", 1.5).toByteArray();
    ByteBuffer b = ByteBuffer.allocate(Frames.MAX_HEADER_BYTES);
    Frames.putHeader(b, Kind.RESPONSE, 123456, 77, true, payload.length);
    ByteBuffer whole = ByteBuffer.allocate(b.remaining() + payload.length);
    whole.put(b).put(payload);
    ArNetPacket body = ArNetPacket.of(123456, 77, true).encodedToBuf(payload);
    assertArrayEquals(Frames.frame(Kind.RESPONSE, body), whole.array());
  }

  @Test
  void recordGoldenBytes() {
    assertEquals("92 02 92 cd 03 e8 ff", hex(enc(Points.ofFlat(new int[] {1000, -1}, 2))));
    ArNetPacket p = new ArNetPacket();
    new LocalizationSnapshot("LOCALIZATION_SUCCESS", 0.5, null, 100, false).write(p);
    assertEquals(
        "95 b4 4c 4f 43 41 4c 49 5a 41 54 49 4f 4e 5f 53 55 43 43 45 53 53"
            + " cb 3f e0 00 00 00 00 00 00 c0 64 c2",
        hex(p.toByteArray()));
  }

  @Test
  void shortestIntegersAgreeWithMessagePack() throws Exception {
    long[] values = {
      0,
      1,
      127,
      128,
      255,
      256,
      65535,
      65536,
      0xffffffffL,
      0x100000000L,
      Long.MAX_VALUE,
      -1,
      -32,
      -33,
      -128,
      -129,
      -32768,
      -32769,
      Integer.MIN_VALUE,
      Integer.MIN_VALUE - 1L,
      Long.MIN_VALUE
    };
    for (long v : values) {
      MessageBufferPacker mp = MessagePack.newDefaultBufferPacker();
      mp.packLong(v);
      byte[] expected = mp.toByteArray();
      ByteBuffer b = ByteBuffer.allocate(9);
      Frames.putInt(b, v);
      assertEquals(expected.length, Frames.intSize(v), "size of " + v);
      assertEquals(hex(expected), hex(java.util.Arrays.copyOf(b.array(), b.position())), "" + v);
    }
  }

  @Test
  void lengthsOutOfRangeAreProtocolErrors() {
    ProtocolException e =
        assertThrows(ProtocolException.class, () -> Frames.checkLength(70_000, 65_536));
    assertEquals(NetError.MALFORMED, e.getCode());
    assertTrue(e.getMessage().contains("70000"), e.getMessage());
    assertThrows(ProtocolException.class, () -> Frames.checkLength(0, 65_536));
    ProtocolException neg = assertThrows(ProtocolException.class, () -> Frames.checkLength(-1, 9));
    assertTrue(neg.getMessage().contains("4294967295"), "shown unsigned: " + neg.getMessage());
    ByteBuffer b = ByteBuffer.wrap(hex("47 45 54 20 2f 20 48 54"));
    assertThrows(ProtocolException.class, () -> Frames.peekLength(b, 65_536), "an HTTP request");
  }
}
