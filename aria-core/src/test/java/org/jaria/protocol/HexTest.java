package org.jaria.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class HexTest {

  @Test
  void parsesTheUsualDumpStyles() {
    byte[] want = {(byte) 0xFA, (byte) 0xFB, 3, 0, 0, 0};
    assertArrayEquals(want, Hex.parse("FA FB 03 00 00 00"));
    assertArrayEquals(want, Hex.parse("fafb03000000"));
    assertArrayEquals(want, Hex.parse("0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00"));
    assertArrayEquals(want, Hex.parse("# sync0\nFA:FB:03 // header\n00 00 00\n"));
  }

  @Test
  void formatIsTheInverseOfParse() {
    byte[] b = new byte[256];
    for (int i = 0; i < 256; i++) {
      b[i] = (byte) i;
    }
    assertArrayEquals(b, Hex.parse(Hex.format(b)));
  }

  @Test
  void badCharacterIsReportedWithLineAndColumn() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> Hex.parse("FA FB\n03 zz"));
    assertTrue(e.getMessage().contains("line 2"), e.getMessage());
    assertEquals(true, e.getMessage().contains("'z'"));
  }
}
