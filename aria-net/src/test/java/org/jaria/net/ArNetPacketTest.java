package org.jaria.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Packets: typed values in, the same values out; anything else a clear, named error. */
class ArNetPacketTest {

  private static ArNetPacket hex(String s) {
    return ArNetPacket.wrap(HexFormat.of().parseHex(s.replace(" ", "")));
  }

  @Test
  void valuesRoundTrip() {
    ArNetPacket p =
        ArNetPacket.of(
            1,
            -70000L,
            2.5,
            "héllo",
            true,
            null,
            new byte[] {1, 2},
            List.of(1, "a"),
            Map.of("k", 2));
    ArNetPacket r = p.toReader();
    assertEquals(1, r.bufToInt());
    assertEquals(-70000L, r.bufToLong());
    assertEquals(2.5, r.bufToDouble());
    assertEquals("héllo", r.bufToStr());
    assertTrue(r.bufToBool());
    assertTrue(r.bufToNil());
    assertArrayEquals(new byte[] {1, 2}, r.bufToData());
    assertEquals(List.of(1L, "a"), r.bufToValue());
    assertEquals(Map.of("k", 2L), r.bufToValue());
    assertFalse(r.hasMore());
    assertEquals(0, r.getRemaining());
    r.resetRead();
    assertEquals(1, r.bufToInt());
  }

  @Test
  void integersReadAsNumbersAndNilAsNullString() {
    ArNetPacket r = ArNetPacket.of(3, null, 7).toReader();
    assertEquals(3.0, r.bufToDouble());
    assertNull(r.bufToStr());
    assertEquals(7, r.bufToInt());
  }

  @Test
  void intsArraysRoundTrip() {
    ArNetPacket p = new ArNetPacket().intsToBuf(new int[] {5, -5, 100000, 9}, 3);
    assertArrayEquals(new int[] {5, -5, 100000}, p.toReader().bufToInts());
  }

  @Test
  void wrongTypeNamesWhatWasExpectedAndFound() {
    ArNetPacket r = ArNetPacket.of("x").toReader();
    ArNetPacketException e = assertThrows(ArNetPacketException.class, r::bufToInt);
    assertEquals("expected an integer as value 1 but found string", e.getMessage());
    ArNetPacket end = ArNetPacket.of(1).toReader();
    end.bufToInt();
    assertEquals(
        "expected a string as value 2 but the packet ended",
        assertThrows(ArNetPacketException.class, end::bufToStr).getMessage());
    ArNetPacket big = ArNetPacket.of(1L << 40).toReader();
    assertTrue(
        assertThrows(ArNetPacketException.class, big::bufToInt)
            .getMessage()
            .contains("too large for a 32-bit integer"));
  }

  @Test
  void lyingLengthsAreCaughtBeforeAllocating() {
    // An array that claims 2^32-1 elements in 5 bytes, a string of 2^32-1 bytes, binary likewise.
    assertThrows(ArNetPacketException.class, () -> hex("dd ff ff ff ff").bufToArray());
    assertThrows(ArNetPacketException.class, () -> hex("db ff ff ff ff 41").bufToStr());
    assertThrows(ArNetPacketException.class, () -> hex("c6 7f ff ff ff 00").bufToData());
    assertThrows(ArNetPacketException.class, () -> hex("df 7f ff ff ff").bufToMap());
    assertThrows(ArNetPacketException.class, () -> hex("c1").bufToValue(), "reserved byte");
    assertThrows(ArNetPacketException.class, () -> hex("cd 01").bufToInt(), "cut short");
  }

  @Test
  void nestingIsLimited() {
    StringBuilder deep = new StringBuilder();
    for (int i = 0; i < 100; i++) {
      deep.append("91 ");
    }
    deep.append("01");
    ArNetPacketException e =
        assertThrows(ArNetPacketException.class, () -> hex(deep.toString()).bufToValue());
    assertTrue(e.getMessage().contains("nested more than"), e.getMessage());
  }

  @Test
  void validateFindsTheFirstBadValueAndKeepsThePosition() {
    ArNetPacket ok = ArNetPacket.of(1, "two", List.of(3.0)).toReader();
    ok.bufToInt();
    ok.validate();
    assertEquals("two", ok.bufToStr(), "position kept");
    assertThrows(ArNetPacketException.class, () -> hex("01 a5 41 42").validate());
  }

  @Test
  void packetsAreEitherForWritingOrForReading() {
    ArNetPacket w = new ArNetPacket().intToBuf(1);
    assertThrows(IllegalStateException.class, w::bufToInt);
    ArNetPacket r = w.toReader();
    assertThrows(IllegalStateException.class, () -> r.intToBuf(2));
    assertThrows(IllegalArgumentException.class, () -> ArNetPacket.of(new Object()));
    assertThrows(IndexOutOfBoundsException.class, () -> ArNetPacket.wrap(new byte[3], 2, 2));
    assertEquals("ArNetPacket[1, <2 bytes>]", ArNetPacket.of(1, new byte[2]).toString());
  }

  @Test
  void randomBytesGiveOnlyPacketErrors() {
    Random rnd = new Random(5);
    int errors = 0;
    for (int i = 0; i < 20_000; i++) {
      byte[] b = new byte[rnd.nextInt(64)];
      rnd.nextBytes(b);
      ArNetPacket p = ArNetPacket.wrap(b);
      try {
        p.validate();
        while (p.hasMore()) {
          p.bufToValue();
        }
      } catch (ArNetPacketException e) {
        errors++;
      }
    }
    assertTrue(errors > 1000, "garbage is mostly refused: " + errors);
  }
}
