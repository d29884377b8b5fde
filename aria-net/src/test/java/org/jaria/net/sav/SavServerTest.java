package org.jaria.net.sav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
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
  void threeHundredIdleSocketsDoNotKeepALoginOut() throws Exception {
    int[] px = new int[160 * 120];
    List<Socket> idle = new ArrayList<>();
    try (SavServer sav = SavServer.open(px::clone, () -> 7, 160, 120, "127.0.0.1", 0)) {
      try {
        for (int i = 0; i < 300; i++) {
          idle.add(new Socket(InetAddress.getLoopbackAddress(), sav.getPort()));
        }
        try (ArClientBase c = new ArClientBase("after-idle-sockets")) {
          c.connect("127.0.0.1", sav.getPort(), "", "");
          assertEquals(160, c.requestOnce("videoSize").get().bufToUByte2());
        }
        long replaced = sav.getServer().getStats().getReplacedPending();
        assertTrue(replaced >= 292, "the stalest idle sockets made room: " + replaced);
      } finally {
        for (Socket s : idle) {
          s.close();
        }
      }
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

  /**
   * What ARIA 2.9.1's serverDemo sent to {@code jaria acts}'s SAV server by hand, through its
   * ArHybridForwarderVideo (docs/networking.md; the first 40 packets): introduction, UDP
   * confirmation, videoSize (260) once, sendVideo (259) with quality 90 once and then with no
   * argument (the argument of serverDemo's own client, getVideoExample, which sent none) each time
   * the last frame is 100 ms old. Each request gets its answer, as serverDemo's forwarder needs.
   */
  @Test
  void serverDemosVideoForwarderIsAnsweredRequestByRequest() throws Exception {
    byte[] sent;
    byte[] answeredThen;
    try (var in = SavServerTest.class.getResourceAsStream("serverDemo-forwarder.c2s.bin");
        var in2 = SavServerTest.class.getResourceAsStream("serverDemo-forwarder.s2c.bin")) {
      sent = in.readAllBytes();
      answeredThen = in2.readAllBytes();
    }
    java.util.List<ArNetPacket> asked = packets(sent);
    assertEquals(260, asked.get(2).getCommand(), "videoSize first");
    assertEquals(259, asked.get(3).getCommand());
    assertEquals(90, asked.get(3).bufToUByte(), "quality 90, as ARIA's forwarder starts");
    assertEquals(0, asked.get(4).getDataLength(), "then the client's argument: none");
    long sendVideos = asked.stream().filter(p -> p.getCommand() == 259).count();
    // By hand: 4061 JPEG bytes at quality 90, then 2366 at the default quality.
    java.util.List<ArNetPacket> then =
        packets(answeredThen).stream().filter(p -> p.getCommand() == 259).toList();
    assertEquals(4065, then.get(0).getDataLength());
    assertEquals(2370, then.get(1).getDataLength());
    java.util.Random r = new java.util.Random(5);
    int[] px = new int[160 * 120];
    for (int i = 0; i < px.length; i++) {
      px[i] = (i % 160) * 0x010101 ^ r.nextInt(0x202020);
    }
    try (SavServer sav = SavServer.open(px::clone, () -> 3, 160, 120, "127.0.0.1", 0);
        java.net.Socket s =
            new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), sav.getPort())) {
      assertEquals(259, sav.getServer().findCommandFromName("sendVideo"));
      assertEquals(260, sav.getServer().findCommandFromName("videoSize"));
      s.setSoTimeout(20_000);
      java.io.DataInputStream in = new java.io.DataInputStream(s.getInputStream());
      // As serverDemo's forwarder did: the login and videoSize, then one sendVideo at a time,
      // each sent once the previous one is answered.
      java.util.List<ArNetPacket> frames = new java.util.ArrayList<>();
      ArNetPacket size = null;
      for (ArNetPacket p : asked) {
        byte[] w = p.toWire();
        s.getOutputStream().write(w);
        if (p.getCommand() != 259) {
          continue;
        }
        while (true) {
          ArNetPacket a = read(in);
          if (a.getCommand() == 260) {
            size = a;
          } else if (a.getCommand() == 259) {
            frames.add(a);
            break;
          }
        }
      }
      assertEquals(sendVideos, frames.size());
      while (size == null) {
        ArNetPacket a = read(in);
        size = a.getCommand() == 260 ? a : null;
      }
      assertEquals(160, size.bufToUByte2());
      assertEquals(120, size.bufToUByte2());
      BufferedImage first =
          ImageIO.read(
              new ByteArrayInputStream(
                  frames.get(0).toByteArray(), 4, frames.get(0).getDataLength() - 4));
      assertEquals(160, first.getWidth());
      assertTrue(
          frames.get(0).getDataLength() > frames.get(1).getDataLength(),
          "quality 90 first, the default after, as recorded");
    }
  }

  private static java.util.List<ArNetPacket> packets(byte[] wire) {
    java.util.List<ArNetPacket> l = new java.util.ArrayList<>();
    for (int i = 0; i < wire.length; ) {
      int len = (wire[i + 2] & 0xff) | (wire[i + 3] & 0xff) << 8;
      l.add(ArNetPacket.fromWire(wire, i, len));
      i += len;
    }
    return l;
  }

  private static ArNetPacket read(java.io.DataInputStream in) throws java.io.IOException {
    byte[] h = new byte[4];
    in.readFully(h);
    int len = (h[2] & 0xff) | (h[3] & 0xff) << 8;
    byte[] w = new byte[len];
    System.arraycopy(h, 0, w, 0, 4);
    in.readFully(w, 4, len - 4);
    return ArNetPacket.fromWire(w, 0, len);
  }
}
