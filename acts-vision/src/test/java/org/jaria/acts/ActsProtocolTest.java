package org.jaria.acts;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jaria.acts.blob.BlobFrame;
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

  /** The worked example of the protocol's documentation, byte by byte. */
  @Test
  void encodesTheDocumentedExample() {
    BlobFrame f = new BlobFrame();
    f.clear(160, 120);
    f.setChannel(
        1,
        1,
        new int[] {1234},
        new int[] {80},
        new int[] {60},
        new int[] {70},
        new int[] {90},
        new int[] {50},
        new int[] {70});
    byte[] r = ActsProtocol.encode(f);
    assertEquals(128 + 16, r.length);
    assertArrayEquals(new byte[] {1, 1, 1, 2}, java.util.Arrays.copyOfRange(r, 0, 4));
    for (int ch = 1; ch < 32; ch++) {
      assertArrayEquals(
          new byte[] {1, 2, 1, 1}, java.util.Arrays.copyOfRange(r, ch * 4, ch * 4 + 4));
    }
    assertArrayEquals(
        new byte[] {1, 1, 0x14, 0x13, 2, 0x11, 1, 0x3D, 2, 7, 2, 0x1B, 1, 0x33, 2, 7},
        java.util.Arrays.copyOfRange(r, 128, 144));
  }

  @Test
  void indicesCountTheBlobsOfEarlierChannels() {
    BlobFrame f = new BlobFrame();
    f.clear(160, 120);
    int[] one = {5, 6};
    f.setChannel(2, 2, new int[] {9, 8}, one, one, one, one, one, one);
    f.setChannel(5, 1, new int[] {7}, one, one, one, one, one, one);
    byte[] r = ActsProtocol.encode(f);
    assertEquals(128 + 3 * 16, r.length);
    assertEquals(0, ActsProtocol.getNumber(r, 4, 2));
    assertEquals(2, ActsProtocol.getNumber(r, 6, 2));
    assertEquals(2, ActsProtocol.getNumber(r, 16, 2), "channel 5 starts after channel 2's two");
    assertEquals(1, ActsProtocol.getNumber(r, 18, 2));
    assertEquals(3, ActsProtocol.getNumber(r, 31 * 4, 2));
    assertEquals(7, ActsProtocol.getNumber(r, 128 + 32, 4));
  }
}
