package org.jaria.acts.sav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import javax.imageio.ImageIO;
import org.jaria.net.ArNetPacket;
import org.jaria.net.client.ArClientBase;
import org.junit.jupiter.api.Test;

/** ARIA's video clients' requests (sendVideo, videoSize) answered with ACTS's frames. */
class SavServerTest {

  @Test
  void sendVideoAnswersAJpegOfTheNewestFrame() throws Exception {
    int[] px = new int[160 * 120];
    java.util.Arrays.fill(px, 0xff0000);
    try (SavServer sav = SavServer.open(px::clone, () -> 7, 160, 120, "127.0.0.1", 0);
        ArClientBase c = new ArClientBase("getVideoExample")) {
      c.connect("127.0.0.1", sav.getPort(), "", "");
      ArNetPacket size = c.requestOnce("videoSize").get();
      assertEquals(160, size.bufToUByte2());
      assertEquals(120, size.bufToUByte2());
      ArNetPacket video = c.requestOnce("sendVideo", (byte) 90).get();
      assertEquals(160, video.bufToUByte2());
      assertEquals(120, video.bufToUByte2());
      BufferedImage img = ImageIO.read(new ByteArrayInputStream(video.remainingBytes()));
      assertEquals(160, img.getWidth());
      int rgb = img.getRGB(80, 60);
      assertTrue(
          ((rgb >> 16) & 0xff) > 200 && (rgb & 0xff) < 60, "red: " + Integer.toHexString(rgb));
    }
  }

  @Test
  void beforeTheFirstFrameTheAnswerIsEmpty() throws Exception {
    try (SavServer sav = SavServer.open(() -> new int[4], () -> 0, 2, 2, null, 0);
        ArClientBase c = new ArClientBase("early")) {
      c.connect("127.0.0.1", sav.getPort(), "", "");
      ArNetPacket video = c.requestOnce("sendVideo").get();
      assertEquals(0, video.bufToUByte2());
      assertEquals(0, video.bufToUByte2());
      assertEquals(0, video.getRemaining());
    }
  }

  /**
   * The bytes ARIA 2.9.1's getVideoExample sent to {@code jaria acts}'s SAV server by hand
   * (docs/networking.md): introduction, UDP confirmation, sendVideo (259) once.
   */
  @Test
  void getVideoExamplesRecordedRequestIsAnswered() throws Exception {
    byte[] sent;
    try (var in = SavServerTest.class.getResourceAsStream("getVideoExample.c2s.bin")) {
      sent = in.readAllBytes();
    }
    int[] px = new int[160 * 120];
    try (SavServer sav = SavServer.open(px::clone, () -> 3, 160, 120, "127.0.0.1", 0);
        java.net.Socket s =
            new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), sav.getPort())) {
      assertEquals(259, sav.getServer().findCommandFromName("sendVideo"));
      java.io.DataInputStream in = new java.io.DataInputStream(s.getInputStream());
      s.getOutputStream().write(sent);
      while (true) {
        byte[] h = new byte[4];
        in.readFully(h);
        int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
        byte[] w = new byte[len];
        System.arraycopy(h, 0, w, 0, 4);
        in.readFully(w, 4, len - 4);
        ArNetPacket p = ArNetPacket.fromWire(w, 0, len);
        if (p.getCommand() == 259) {
          assertEquals(160, p.bufToUByte2());
          assertEquals(120, p.bufToUByte2());
          assertTrue(p.getRemaining() > 100, "a JPEG follows");
          return;
        }
      }
    }
  }
}
