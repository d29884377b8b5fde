package org.jaria.acts;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class ActsProtocolTest {

  @Test
  void numbersAreBase64DigitsPlusOne() {
    byte[] b = new byte[4];
    ActsProtocol.putNumber(0, 2, b, 0);
    assertArrayEquals(new byte[] {1, 1, 0, 0}, b);
    ActsProtocol.putNumber(4095, 2, b, 2);
    assertArrayEquals(new byte[] {1, 1, 64, 64}, b);
    ActsProtocol.putNumber(1234, 4, b, 0); // 1234 = 19*64 + 18
    assertArrayEquals(new byte[] {1, 1, 20, 19}, b);
    assertEquals(1234, ActsProtocol.getNumber(b, 0, 4));
    ActsProtocol.putNumber(99_999_999, 4, b, 0);
    assertEquals(ActsProtocol.MAX_4_DIGITS, ActsProtocol.getNumber(b, 0, 4), "clamped");
    assertEquals(-1, ActsProtocol.getNumber(new byte[] {0, 1}, 0, 2), "0 is never a digit");
    assertEquals(-1, ActsProtocol.getNumber(new byte[] {65, 1}, 0, 2));
  }
}
