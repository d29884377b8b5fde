package org.jaria.net.video;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;
import javax.imageio.ImageIO;
import org.jaria.net.Eventually;
import org.jaria.net.data.VideoFrame;
import org.junit.jupiter.api.Test;

/** Pictures from a grabber become JPEG frames; a camera that fails now and then is survived. */
class JpegVideoTest {

  @Test
  void grabbedPicturesBecomeNumberedJpegFrames() throws Exception {
    try (JpegVideo v =
        new JpegVideo(
            "red",
            64,
            48,
            50,
            rgb -> {
              Arrays.fill(rgb, 0xFF0000);
              return true;
            })) {
      Eventually.until("a first frame", () -> v.getLatestFrame() != null);
      VideoFrame first = v.getLatestFrame();
      assertEquals(VideoFrame.Format.JPEG, first.getFormat());
      BufferedImage img = ImageIO.read(new ByteArrayInputStream(first.getData()));
      assertEquals(64, img.getWidth());
      int rgb = img.getRGB(32, 24);
      assertTrue(
          ((rgb >> 16) & 0xFF) > 200 && (rgb & 0xFF) < 60, "red: " + Integer.toHexString(rgb));
      Eventually.until(
          "a newer frame while watched",
          () -> v.getLatestFrame().getSequence() > first.getSequence());
      assertEquals("red", v.getName());
    }
  }

  @Test
  void aCameraThatFailsOrHasNothingNewDoesNotStopTheVideo() throws Exception {
    AtomicInteger calls = new AtomicInteger();
    try (JpegVideo v =
        new JpegVideo(
            "flaky",
            16,
            16,
            100,
            rgb -> {
              int n = calls.incrementAndGet();
              if (n % 3 == 0) {
                throw new IOException("the camera hiccuped");
              }
              return n % 3 == 1; // every third call has a new picture
            })) {
      Eventually.until(
          "frames despite failures",
          () -> {
            VideoFrame f = v.getLatestFrame();
            return f != null && f.getSequence() >= 3;
          });
      assertTrue(calls.get() >= 7, "kept grabbing after failures: " + calls.get());
    }
  }

  @Test
  void nonsenseSizesAreRefused() {
    assertThrows(IllegalArgumentException.class, () -> new JpegVideo("x", 0, 10, 5, rgb -> true));
    assertThrows(IllegalArgumentException.class, () -> new JpegVideo("x", 10, 10, 0, rgb -> true));
  }
}
