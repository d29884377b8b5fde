package org.jaria.acts.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.blob.BlobFrame;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.StillImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.clock.Clock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class ActsServerTest {

  private ChannelBank bank;
  private ActsServer server;

  @BeforeEach
  void start() throws Exception {
    bank = new ChannelBank();
    Trainer t = new Trainer(bank);
    var scene = TestScene.render(160, 120);
    TestScene.Box book = TestScene.BOOK.scaled(160, 120);
    TestScene.Box cup = TestScene.CUP.scaled(160, 120);
    t.addRect(scene, book.x0(), book.y0(), book.x1(), book.y1());
    t.addRect(scene, cup.x0(), cup.y0(), cup.x1(), cup.y1());
    bank.setTrackedBlobs(1, 2);
    server = start(new StillImageSource(scene), ServerSettings.DEFAULT.withMaxClients(4));
  }

  private ActsServer start(ImageSource src, ServerSettings s) throws Exception {
    ActsServer srv =
        new ActsServer(
            new VisionPipeline(src, bank, TrackerSettings.DEFAULT),
            s.withAddress("127.0.0.1", 0),
            Clock.system());
    srv.start();
    assertTrue(srv.awaitFrames(1, 10, TimeUnit.SECONDS));
    return srv;
  }

  @AfterEach
  void stop() {
    server.stop();
    assertServerThreadsGone(server.getPort());
  }

  private static void assertServerThreadsGone(int port) {
    for (Thread t : Thread.getAllStackTraces().keySet()) {
      assertFalse(
          t.getName().startsWith("acts-" + port + "-") && t.isAlive(),
          "thread " + t.getName() + " still running");
    }
  }

  private ArACTS_1_2 client() {
    ArACTS_1_2 acts = new ArACTS_1_2();
    assertTrue(acts.openPort("127.0.0.1", server.getPort()), acts.getOpenMessage());
    acts.setReadTimeouts(5000, 5000);
    return acts;
  }

  @Test
  void roundTripWithTheTutorialImage() {
    try (ArACTS_1_2 acts = client()) {
      assertTrue(acts.requestPacket());
      assertTrue(acts.receiveBlobInfo());
      assertEquals(2, acts.getNumBlobs(1));
      BlobFrame expected = server.latestFrame();
      ArACTSBlob blob = new ArACTSBlob();
      for (int n = 1; n <= 2; n++) {
        assertTrue(acts.getBlob(1, n, blob));
        var e = expected.getBlob(1, n);
        assertEquals(e.area(), blob.getArea());
        assertEquals(e.xcg(), blob.getXCG());
        assertEquals(e.ycg(), blob.getYCG());
        assertEquals(e.left(), blob.getLeft());
        assertEquals(e.right(), blob.getRight());
        assertEquals(e.top(), blob.getTop());
        assertEquals(e.bottom(), blob.getBottom());
      }
      acts.getBlob(1, 1, blob);
      TestScene.Box book = TestScene.BOOK_EXTENT.scaled(160, 120);
      assertTrue(book.contains(blob.getXCG(), blob.getYCG()), blob.toString());
      for (int c = 2; c <= 32; c++) {
        assertEquals(0, acts.getNumBlobs(c));
      }
    }
    assertEquals(1, server.requestsServed());
  }

  @Test
  void manyClientsAtOnce() throws Exception {
    ExecutorService pool = Executors.newFixedThreadPool(4);
    try {
      List<Future<Integer>> results = new ArrayList<>();
      for (int i = 0; i < 4; i++) {
        results.add(
            pool.submit(
                (Callable<Integer>)
                    () -> {
                      int ok = 0;
                      try (ArACTS_1_2 acts = client()) {
                        for (int k = 0; k < 50; k++) {
                          acts.requestPacket();
                          if (acts.receiveBlobInfo() && acts.getNumBlobs(1) == 2) {
                            ok++;
                          }
                        }
                      }
                      return ok;
                    }));
      }
      for (Future<Integer> f : results) {
        assertEquals(50, f.get(30, TimeUnit.SECONDS));
      }
    } finally {
      pool.shutdown();
      assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
    }
    assertEquals(200, server.requestsServed());
  }

  @Test
  void garbageAndVanishingClientsDoNotHurtOthers() throws Exception {
    try (ArACTS_1_2 good = client()) {
      // A client that sends garbage, then one request (whose answer proves the garbage was
      // read), then many requests it never reads, then vanishes with a reset.
      Socket rude = new Socket(InetAddress.getLoopbackAddress(), server.getPort());
      OutputStream out = rude.getOutputStream();
      out.write(
          "hello ACTS\r\n\u0000\u00ff0".getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
      out.flush();
      int replyLength = ActsReply.encode(server.latestFrame()).length;
      assertEquals(replyLength, rude.getInputStream().readNBytes(replyLength).length);
      for (int i = 0; i < 200; i++) {
        out.write('0');
      }
      out.flush();
      rude.setSoLinger(true, 0); // reset, not a clean close
      rude.close();
      // A client that disconnects in the middle of nothing.
      new Socket(InetAddress.getLoopbackAddress(), server.getPort()).close();
      for (int k = 0; k < 20; k++) {
        good.requestPacket();
        assertTrue(good.receiveBlobInfo());
        assertEquals(2, good.getNumBlobs(1));
      }
    }
    assertEquals(14, server.garbageBytes());
  }

  @Test
  void repliesAreExactlyTheEncodedLatestFrame() throws Exception {
    try (Socket s = new Socket(InetAddress.getLoopbackAddress(), server.getPort())) {
      s.getOutputStream().write('0');
      byte[] expected = ActsReply.encode(server.latestFrame());
      byte[] got = s.getInputStream().readNBytes(expected.length);
      assertArrayEquals(expected, got);
    }
  }

  @Test
  void clientsBeyondTheLimitAreRefused() throws Exception {
    List<ArACTS_1_2> held = new ArrayList<>();
    try {
      for (int i = 0; i < 4; i++) {
        ArACTS_1_2 a = client();
        a.requestPacket();
        assertTrue(a.receiveBlobInfo()); // the connection is really being served
        held.add(a);
      }
      try (Socket extra = new Socket(InetAddress.getLoopbackAddress(), server.getPort())) {
        extra.setSoTimeout(5000);
        extra.getOutputStream().write('0');
        InputStream in = extra.getInputStream();
        assertEquals(-1, readOrEof(in), "refused: closed without a reply");
      }
      assertEquals(1, server.clientsRefused());
    } finally {
      held.forEach(ArACTS_1_2::closePort);
    }
  }

  private static int readOrEof(InputStream in) {
    try {
      return in.read();
    } catch (IOException e) {
      return -1; // connection reset counts as refused too
    }
  }

  @Test
  void quitEndsOnlyTheClientByDefault() throws Exception {
    try (ArACTS_1_2 quitter = client();
        ArACTS_1_2 other = client()) {
      assertTrue(quitter.requestQuit());
      other.requestPacket();
      assertTrue(other.receiveBlobInfo());
    }
  }

  @Test
  void quitStopsTheServerWhenAllowed() throws Exception {
    ActsServer quitting =
        start(
            new StillImageSource(TestScene.render(160, 120)),
            ServerSettings.DEFAULT.withQuitOnRequest(true));
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("127.0.0.1", quitting.getPort()));
      acts.requestQuit();
      quitting.awaitStopRequest();
    } finally {
      quitting.stop();
    }
    assertServerThreadsGone(quitting.getPort());
  }

  @Test
  void trainingChangesReachClientsWhileServing() throws Exception {
    try (ArACTS_1_2 acts = client()) {
      new Trainer(bank).clearTraining();
      // counted after the change: frame before + 1 may have started with the old tables, frame
      // before + 2 starts once it is out, so after the change
      long before = server.framesProcessed();
      assertTrue(server.awaitFrames(before + 2, 10, TimeUnit.SECONDS));
      acts.requestPacket();
      assertTrue(acts.receiveBlobInfo());
      assertEquals(0, acts.getNumBlobs(1));
    }
  }

  @Test
  void aSecondServerOnTheSamePortFailsClearly() {
    ActsServer second =
        new ActsServer(
            new VisionPipeline(
                new StillImageSource(TestScene.render(160, 120)), bank, TrackerSettings.DEFAULT),
            ServerSettings.DEFAULT.withAddress("127.0.0.1", server.getPort()),
            Clock.system());
    IOException e = assertThrows(IOException.class, second::start);
    assertTrue(
        e.getMessage().contains("cannot listen on port " + server.getPort()), e.getMessage());
    second.stop();
  }

  @Test
  void aFailingSourceIsReportedAndServingContinues() throws Exception {
    java.util.concurrent.CountDownLatch tried = new java.util.concurrent.CountDownLatch(1);
    ImageSource failing =
        new ImageSource() {
          @Override
          public int width() {
            return 160;
          }

          @Override
          public int height() {
            return 120;
          }

          @Override
          public boolean nextFrame(int[] rgb) throws IOException {
            tried.countDown();
            throw new IOException("camera unplugged");
          }
        };
    ActsServer s =
        new ActsServer(
            new VisionPipeline(failing, bank, TrackerSettings.DEFAULT),
            ServerSettings.DEFAULT.withAddress("127.0.0.1", 0),
            Clock.system());
    s.start();
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("127.0.0.1", s.getPort()));
      acts.setReadTimeouts(5000, 5000);
      acts.requestPacket();
      assertTrue(acts.receiveBlobInfo(), "an empty reply while no frame is available");
      assertEquals(0, acts.getNumBlobs(1));
      // The pipeline thread may not have asked the camera yet; once it has, stop() joins it, so
      // the failure it was counting is counted.
      assertTrue(tried.await(10, TimeUnit.SECONDS), "the server asked the camera for a frame");
    } finally {
      s.stop();
    }
    assertTrue(s.sourceErrors() >= 1);
    assertServerThreadsGone(s.getPort());
  }

  @Test
  void stopIsIdempotentAndTooLargeImagesAreRefused() {
    server.stop();
    server.stop();
    assertThrows(
        IllegalArgumentException.class,
        () ->
            new ActsServer(
                new VisionPipeline(
                    new StillImageSource(new org.jaria.acts.image.RgbImage(5000, 2)),
                    bank,
                    TrackerSettings.DEFAULT),
                ServerSettings.DEFAULT,
                Clock.system()));
  }
}
