package org.jaria.acts.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.jaria.acts.ActsProtocol;
import org.jaria.acts.blob.BlobFrame;
import org.junit.jupiter.api.Test;

class ActsReplyTest {

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
    byte[] r = ActsReply.encode(f);
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
    byte[] r = ActsReply.encode(f);
    assertEquals(128 + 3 * 16, r.length);
    assertEquals(0, ActsProtocol.getNumber(r, 4, 2));
    assertEquals(2, ActsProtocol.getNumber(r, 6, 2));
    assertEquals(2, ActsProtocol.getNumber(r, 16, 2), "channel 5 starts after channel 2's two");
    assertEquals(1, ActsProtocol.getNumber(r, 18, 2));
    assertEquals(3, ActsProtocol.getNumber(r, 31 * 4, 2));
    assertEquals(7, ActsProtocol.getNumber(r, 128 + 32, 4));
  }
}
