package org.jaria.tools.guiserver;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.TestScene;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.data.VideoFrame;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code jaria demo guiserver} driving a robot it reaches by TCP (a simulator standing in for a
 * real Pioneer), serving a picture as the camera's video, through the real command line and a real
 * client (real time: a few seconds).
 */
@Tag("slow")
class GuiServerCommandTest {

  /** Output that lets the test wait for the line saying where the server listens. */
  private static final class Output extends Writer {
    private final StringBuilder text = new StringBuilder();
    final CountDownLatch listening = new CountDownLatch(1);

    synchronized String text() {
      return text.toString();
    }

    @Override
    public synchronized void write(char[] buf, int off, int len) {
      text.append(buf, off, len);
      if (text.indexOf("Listening on ") >= 0 && text.indexOf("Watch it with") >= 0) {
        listening.countDown();
      }
    }

    @Override
    public void flush() {}

    @Override
    public void close() {}
  }

  @Test
  void drivesARobotOverTcpAndServesAPictureAsVideo(@TempDir Path dir) throws Exception {
    Path picture = dir.resolve("scene.png");
    ImageFiles.write(TestScene.render(), picture);
    try (SimWorld world =
        SimWorld.bundled("office", SimOptions.builder().basePort(0).seed(2).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      world.listen();
      world.startRealTime(1);
      CommandLine cli = JariaCli.commandLine();
      Output out = new Output();
      StringWriter err = new StringWriter();
      cli.setOut(new PrintWriter(out, true));
      cli.setErr(new PrintWriter(err, true));
      CompletableFuture<Integer> run =
          CompletableFuture.supplyAsync(
              () ->
                  cli.execute(
                      "demo",
                      "guiserver",
                      "--map",
                      "office",
                      "--remote",
                      "127.0.0.1:" + r.getPort(),
                      "--video",
                      picture.toString(),
                      "--port",
                      "0",
                      "--seconds",
                      "8"));
      assertTrue(out.listening.await(60, TimeUnit.SECONDS), "listening: " + out.text() + err);
      String text = out.text();
      assertTrue(text.contains("Serving video: scene.png"), text);
      assertTrue(text.contains("Localized at home: yes"), text);
      Matcher m = Pattern.compile("Listening on [0-9.]+:(\\d+)").matcher(text);
      assertTrue(m.find(), text);
      int port = Integer.parseInt(m.group(1));

      try (ArClientBase c = new ArClientBase("test")) {
        c.connect("127.0.0.1", port, "", "");
        assertEquals(
            "scene.png", c.requestOnce("getVideoInfo").get(10, TimeUnit.SECONDS).bufToStr());
        CompletableFuture<VideoFrame> frame = new CompletableFuture<>();
        c.addHandler("getVideo", p -> frame.complete(VideoFrame.read(p)));
        c.request("getVideo", 100).get(10, TimeUnit.SECONDS);
        VideoFrame f = frame.get(20, TimeUnit.SECONDS);
        assertEquals(VideoFrame.Format.JPEG, f.getFormat());
        BufferedImage img = ImageIO.read(new ByteArrayInputStream(f.getData()));
        assertNotNull(img, "a JPEG the client can decode");
        assertEquals(320, img.getWidth());
        assertEquals(240, img.getHeight());
      }
      assertEquals(0, run.get(60, TimeUnit.SECONDS), err.toString());
    }
  }

  @Test
  void contradictoryOrMisplacedOptionsAreRefusedWithTheReason() {
    String[][] cases = {
      {"--camera", "0"},
      {"--remote", "127.0.0.1:1", "--serial", "/dev/ttyS0"},
      {"--remote", "127.0.0.1:1", "--camera", "0", "--video", "x.png"},
      {"--remote", "127.0.0.1:1", "--video", "x.png", "--forward-video", "localhost"},
      {"--forward-video", "localhost:seventy"},
      {"--bind", "0.0.0.0"},
      {"--no-login", "--password", "secret"}
    };
    String[] reasons = {
      "--camera, --video and --ptz are for a real robot",
      "--remote or --serial, not both",
      "--camera or --video, not both",
      "--forward-video or --camera/--video, not both",
      "--forward-video wants HOST or HOST:PORT, got 'localhost:seventy'",
      "--bind 0.0.0.0 without a password would let anybody who can reach port 7272 drive the"
          + " robot",
      "--no-login or a password"
    };
    for (int i = 0; i < cases.length; i++) {
      CommandLine cli = JariaCli.commandLine();
      StringWriter err = new StringWriter();
      cli.setOut(new PrintWriter(new StringWriter(), true));
      cli.setErr(new PrintWriter(err, true));
      String[] args = new String[cases[i].length + 2];
      args[0] = "demo";
      args[1] = "guiserver";
      System.arraycopy(cases[i], 0, args, 2, cases[i].length);
      assertEquals(2, cli.execute(args), String.join(" ", args));
      assertTrue(err.toString().contains(reasons[i]), err.toString());
    }
  }

  @Test
  void theListeningLineSaysWhoMayConnect() {
    assertEquals(
        "Listening on 0.0.0.0:7272 (NO LOGIN: anybody who can reach this port may drive the"
            + " robot)",
        GuiServerCommand.listeningLine("0.0.0.0", 7272, true));
    assertTrue(
        GuiServerCommand.listeningLine("127.0.0.1", 7272, true)
            .contains("no login needed; this computer only"));
    assertTrue(
        GuiServerCommand.listeningLine("0.0.0.0", 7272, false)
            .contains("login required; the login is weak"));
    assertEquals(
        "Listening on 127.0.0.1:7272 (login required; this computer only)",
        GuiServerCommand.listeningLine("127.0.0.1", 7272, false));
  }

  /**
   * docs/networking.md's recipe: the guiServer passes on a SAV server's pictures ({@code jaria
   * acts}'s, here its SavServer on a free port) as {@code sendVideo}, byte for byte.
   */
  @Test
  void forwardsAVideoServersPictures() throws Exception {
    int[] px = new int[160 * 120];
    java.util.Arrays.fill(px, 0x3366cc);
    try (SimWorld world =
            SimWorld.bundled("office", SimOptions.builder().basePort(0).seed(2).build());
        org.jaria.net.sav.SavServer sav =
            org.jaria.net.sav.SavServer.open(px::clone, () -> 1, 160, 120, "127.0.0.1", 0);
        ArClientBase direct = new ArClientBase("direct")) {
      SimRobot r = world.addRobot("p3dx-sh");
      world.listen();
      world.startRealTime(1);
      direct.connect("127.0.0.1", sav.getPort(), "", "");
      byte[] fromSav =
          direct.requestOnce("sendVideo", (byte) 90).get(10, TimeUnit.SECONDS).remainingBytes();
      CommandLine cli = JariaCli.commandLine();
      Output out = new Output();
      StringWriter err = new StringWriter();
      cli.setOut(new PrintWriter(out, true));
      cli.setErr(new PrintWriter(err, true));
      CompletableFuture<Integer> run =
          CompletableFuture.supplyAsync(
              () ->
                  cli.execute(
                      "demo",
                      "guiserver",
                      "--map",
                      "office",
                      "--remote",
                      "127.0.0.1:" + r.getPort(),
                      "--forward-video",
                      "127.0.0.1:" + sav.getPort(),
                      "--port",
                      "0",
                      "--seconds",
                      "8"));
      assertTrue(out.listening.await(60, TimeUnit.SECONDS), "listening: " + out.text() + err);
      String text = out.text();
      assertTrue(text.contains("Forwarding video from 127.0.0.1:" + sav.getPort()), text);
      Matcher m = Pattern.compile("Listening on [0-9.]+:(\\d+)").matcher(text);
      assertTrue(m.find(), text);
      try (ArClientBase c = new ArClientBase("getVideoExample")) {
        c.connect("127.0.0.1", Integer.parseInt(m.group(1)), "", "");
        byte[] got = new byte[0];
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (got.length <= 4 && System.nanoTime() < end) {
          got = c.requestOnce("sendVideo", (byte) 90).get(10, TimeUnit.SECONDS).remainingBytes();
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(fromSav, got, "the SAV server's frame");
      }
      assertEquals(0, run.get(60, TimeUnit.SECONDS), err.toString());
    }
  }
}
