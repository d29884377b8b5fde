package org.jaria.net.forward;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import org.jaria.net.ArNetPacket;
import org.jaria.net.Eventually;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.VideoFrame;
import org.jaria.net.provider.VideoSource;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.Where;
import org.jaria.net.server.info.ArServerHandlerVideo;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A forwarder between a real video server (an ArServerBase with a camera, what {@code jaria acts}'s
 * SAV server is) and its own clients, with a {@link VideoGate} in between that makes the video
 * server leave, stall, flood and talk garbage. The forwarder's server must keep serving its other
 * clients through all of it, and never hang.
 */
@Timeout(120)
class ArHybridForwarderVideoTest {

  private static final byte[] JPEG = jpeg(160, 120);

  private ArServerBase videoServer;
  private VideoGate gate;
  private ArServerBase server;
  private ArHybridForwarderVideo forwarder;
  private ArClientBase viewer;
  private final AtomicLong skewNanos = new AtomicLong();

  @BeforeEach
  void start() throws Exception {
    videoServer = new ArServerBase(ServerOptions.builder().port(0).serverName("SAV").build());
    new ArServerHandlerVideo(videoServer, camera());
    videoServer.open();
    gate = new VideoGate(videoServer.getPort());
    server = new ArServerBase(ServerOptions.builder().port(0).serverName("robot").build());
    server.addData(
        "ping",
        "answers pong",
        "none",
        "string",
        "",
        Where.WORKER,
        (c, q, r) -> r.strToBuf("pong"));
    forwarder =
        new ArHybridForwarderVideo(
            server,
            "127.0.0.1",
            gate.getPort(),
            Duration.ofMillis(500),
            () -> System.nanoTime() + skewNanos.get());
    server.open();
    viewer = new ArClientBase("viewer");
    viewer.connect("127.0.0.1", server.getPort(), "", "");
  }

  @AfterEach
  void stop() throws Exception {
    viewer.close();
    forwarder.close();
    server.close();
    gate.close();
    videoServer.close();
  }

  @Test
  void clientsGetTheVideoServersFramesByteForByte() throws Exception {
    byte[] frame = Eventually.value("a forwarded frame", this::frameOrNull);
    assertEquals(160, le16(frame, 0));
    assertEquals(120, le16(frame, 2));
    assertArrayEquals(JPEG, java.util.Arrays.copyOfRange(frame, 4, frame.length));
    ArNetPacket size = viewer.requestOnce("videoSize").get();
    assertEquals(160, size.bufToUByte2(), "the size the video server gave");
    assertEquals(120, size.bufToUByte2());
    assertTrue(forwarder.isForwardingVideo());
    ForwarderStats s = forwarder.getStats();
    assertEquals(1, s.connects());
    assertEquals(0, s.dropped());
    assertTrue(s.frames() >= 1 && s.requests() >= s.frames(), s.toString());
  }

  @Test
  void aVideoServerThatLeavesIsForgottenThenFoundAgain() throws Exception {
    Eventually.value("a forwarded frame", this::frameOrNull);
    gate.cutAll();
    Eventually.until("the lost server counted", () -> forwarder.getStats().lost() >= 1);
    // No stale picture: until the server is back the answer is ARIA's "no frame" (0 x 0).
    ArNetPacket none = viewer.requestOnce("sendVideo").get();
    if (!forwarder.isForwardingVideo()) {
      assertEquals(0, none.bufToUByte2());
    }
    assertEquals("pong", viewer.requestOnce("ping").get().bufToStr(), "others are still served");
    Eventually.until("reconnected", () -> forwarder.getStats().connects() >= 2);
    Eventually.value("a frame after reconnecting", this::frameOrNull);
  }

  @Test
  void garbageAndSilenceAreFailedConnectionsNotHangs() throws Exception {
    Eventually.value("a forwarded frame", this::frameOrNull);
    gate.setMode(VideoGate.Mode.GARBAGE);
    gate.cutAll();
    long failed = forwarder.getStats().failedConnects();
    Eventually.until(
        "two failed attempts on garbage",
        () -> forwarder.getStats().failedConnects() >= failed + 2);
    assertEquals(0, le16(viewer.requestOnce("sendVideo").get().remainingBytes(), 0), "no frame");
    gate.setMode(VideoGate.Mode.SILENT);
    long failed2 = forwarder.getStats().failedConnects();
    Eventually.until(
        "a silent server times out", () -> forwarder.getStats().failedConnects() >= failed2 + 1);
    assertEquals("pong", viewer.requestOnce("ping").get().bufToStr(), "others are still served");
    gate.setMode(VideoGate.Mode.RELAY);
    Eventually.value("a frame once the server is sane again", this::frameOrNull);
  }

  @Test
  void garbageInTheMiddleOfTheStreamDropsTheConnectionAndItComesBack() throws Exception {
    Eventually.value("a forwarded frame", this::frameOrNull);
    gate.inject(new byte[] {0x0f, 0x0c, (byte) 0xff, (byte) 0xff, 1, 2, 3, 4, 5, 6, 7, 8});
    Eventually.until("the broken stream counted", () -> forwarder.getStats().lost() >= 1);
    Eventually.until("reconnected", () -> forwarder.getStats().connects() >= 2);
    Eventually.value("a frame after reconnecting", this::frameOrNull);
  }

  @Test
  void aFloodOfBigFramesNobodyAskedForIsDroppedAndCounted() throws Exception {
    Eventually.value("a forwarded frame", this::frameOrNull);
    int sendVideo = videoServer.findCommandFromName("sendVideo");
    gate.holdBack(sendVideo); // only the flood's frames reach the forwarder from now on
    long framesBefore = forwarder.getStats().frames();
    long droppedBefore = forwarder.getStats().dropped();
    byte[] body = new byte[ArNetPacket.MAX_DATA_LENGTH];
    body[0] = (byte) 160;
    body[2] = 120;
    body[4] = (byte) 0xff;
    body[5] = (byte) 0xd8;
    ArNetPacket big = new ArNetPacket(sendVideo);
    big.dataToBuf(body);
    byte[] wire = big.toWire();
    int flood = 300;
    for (int i = 0; i < flood; i++) {
      gate.inject(wire);
    }
    assertEquals("pong", viewer.requestOnce("ping").get().bufToStr(), "served during the flood");
    // Every flooded packet is either taken as the answer to an outstanding request or dropped.
    Eventually.until(
        "all " + flood + " accounted for",
        () -> {
          ForwarderStats s = forwarder.getStats();
          return s.frames() - framesBefore + s.dropped() - droppedBefore == flood;
        });
    ForwarderStats s = forwarder.getStats();
    assertTrue(s.frames() - framesBefore <= s.requests(), "taken only when asked: " + s);
    assertTrue(s.dropped() - droppedBefore > 0, "some dropped: " + s);
    assertTrue(forwarder.isForwardingVideo(), "a flood of valid packets is not a reason to leave");
  }

  @Test
  void aVideoServerThatStopsAnsweringIsDroppedAfterTenSeconds() throws Exception {
    Eventually.value("a forwarded frame", this::frameOrNull);
    gate.holdBack(videoServer.findCommandFromName("sendVideo"));
    Eventually.until("a request outstanding", () -> forwarder.getStats().requests() >= 2);
    // Ten seconds pass on the forwarder's clock without an answer.
    skewNanos.addAndGet(Duration.ofSeconds(11).toNanos());
    Eventually.until("the stall counted", () -> forwarder.getStats().stalls() >= 1);
    gate.holdBack(-1);
    Eventually.until("reconnected", () -> forwarder.getStats().connects() >= 2);
    Eventually.value("a frame after the stall", this::frameOrNull);
  }

  @Test
  void closingWhileTheVideoServerIsSilentReturns() throws Exception {
    gate.setMode(VideoGate.Mode.SILENT);
    gate.cutAll();
    Eventually.until("connecting to a silent server", () -> gate.openLinks() >= 1);
    forwarder.close(); // the assertion is that this returns (the class has a timeout)
    assertTrue(!forwarder.isForwardingVideo());
  }

  private byte[] frameOrNull() {
    try {
      byte[] b = viewer.requestOnce("sendVideo", (byte) 80).get().remainingBytes();
      return b.length > 4 ? b : null;
    } catch (Exception e) {
      throw new AssertionError(e);
    }
  }

  private static int le16(byte[] b, int at) {
    return (b[at] & 0xff) | (b[at + 1] & 0xff) << 8;
  }

  private static VideoSource camera() {
    VideoFrame f = new VideoFrame(1, VideoFrame.Format.JPEG, 160, 120, JPEG);
    return new VideoSource() {
      @Override
      public String getName() {
        return "SAV";
      }

      @Override
      public VideoFrame getLatestFrame() {
        return f;
      }
    };
  }

  private static byte[] jpeg(int w, int h) {
    BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
    for (int y = 0; y < h; y++) {
      for (int x = 0; x < w; x++) {
        img.setRGB(x, y, (x * 255 / w) << 16 | (y * 255 / h) << 8);
      }
    }
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    try {
      ImageIO.write(img, "jpg", out);
    } catch (java.io.IOException e) {
      throw new java.io.UncheckedIOException(e);
    }
    return out.toByteArray();
  }
}
