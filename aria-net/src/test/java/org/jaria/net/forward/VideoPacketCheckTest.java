package org.jaria.net.forward;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** What a forwarder passes on from its video server, and what it drops. */
class VideoPacketCheckTest {

  private static byte[] frame(int w, int h, int... bytes) {
    byte[] b = new byte[4 + bytes.length];
    b[0] = (byte) w;
    b[1] = (byte) (w >> 8);
    b[2] = (byte) h;
    b[3] = (byte) (h >> 8);
    for (int i = 0; i < bytes.length; i++) {
      b[4 + i] = (byte) bytes[i];
    }
    return b;
  }

  @Test
  void aJpegFrameAndTheEmptyFramePass() {
    assertNull(VideoPacketCheck.whyNotAFrame(frame(160, 120, 0xff, 0xd8, 0xff, 0xe0)));
    assertNull(VideoPacketCheck.whyNotAFrame(frame(0, 0)), "no picture yet");
  }

  @Test
  void anythingElseIsSaidWhy() {
    assertEquals(
        "a video packet of 3 bytes (it needs at least a width and height)",
        VideoPacketCheck.whyNotAFrame(new byte[3]));
    assertEquals(
        "a 160 x 120 frame whose bytes are not a JPEG",
        VideoPacketCheck.whyNotAFrame(frame(160, 120, 'G', 'I', 'F', '8')));
    assertEquals(
        "a 160 x 120 frame whose bytes are not a JPEG",
        VideoPacketCheck.whyNotAFrame(frame(160, 120)),
        "a size with no picture");
    assertEquals("a frame of 0 x 120 pixels", VideoPacketCheck.whyNotAFrame(frame(0, 120, 0xff)));
    assertEquals("a 0 x 0 frame with 2 bytes", VideoPacketCheck.whyNotAFrame(frame(0, 0, 1, 2)));
    assertEquals(
        "a video size of 65535 x 120 pixels",
        VideoPacketCheck.whyNotAFrame(frame(65535, 120, 0xff, 0xd8, 0, 0)));
  }

  @Test
  void aSizeNeedsFourBytesOfSensibleSides() {
    assertNull(VideoPacketCheck.whyNotASize(frame(320, 240)));
    assertNull(VideoPacketCheck.whyNotASize(frame(0, 0)), "no video yet");
    assertEquals("a video size of 8193 x 1 pixels", VideoPacketCheck.whyNotASize(frame(8193, 1)));
  }
}
