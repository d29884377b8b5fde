package org.jaria.tools.acts;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ChannelLutFile;
import org.jaria.acts.color.Trainer;
import org.jaria.acts.config.ActsConfig;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.RgbImage;
import org.jaria.acts.image.TestScene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class ActsCommandTest {

  @TempDir Path dir;

  private final StringWriter out = new StringWriter();
  private final StringWriter err = new StringWriter();

  private CommandLine cli(ActsCommand cmd) {
    CommandLine c = new CommandLine(cmd);
    c.setOut(new PrintWriter(out, true));
    c.setErr(new PrintWriter(err, true));
    return c;
  }

  @Test
  void helpListsActsOptions() {
    assertEquals(0, cli(new ActsCommand()).execute("-h"));
    String help = out.toString();
    for (String opt :
        List.of(
            "-c", "-d", "-f", "-G", "-H", "-i", "-n", "-p", "-P", "-R", "-s", "-S", "-t", "-V",
            "-w", "-W", "-x")) {
      assertTrue(help.contains("\n  " + opt), "help describes " + opt + ":\n" + help);
    }
  }

  /** Without the camera driver (module acts-camera, in apps) -P says how to get it. */
  @Test
  void cameraParametersWithoutTheDriverSayWhatToAdd() {
    assertEquals(1, cli(new ActsCommand()).execute("-P"));
    assertTrue(err.toString().contains("org.jaria:acts-camera"), err.toString());
  }

  @Test
  void badOptionsAreUsageErrors() {
    assertEquals(2, cli(new ActsCommand()).execute("-p", "notaport"));
    assertTrue(err.toString().contains("-p"), err.toString());
  }

  /** Without the camera driver a camera device says how to get it; still images need nothing. */
  @Test
  void aCameraWithoutTheDriverSaysWhatToAdd() {
    assertEquals(1, cli(new ActsCommand()).execute("-d", "99", "-p", "0"));
    assertTrue(err.toString().contains("org.jaria:acts-camera"), err.toString());
    assertTrue(err.toString().contains("-f FILE"), err.toString());
  }

  @Test
  void missingConfigurationGivesAClearMessage() {
    assertEquals(
        1, cli(new ActsCommand()).execute("-c", dir.resolve("none").toString(), "-p", "0"));
    assertTrue(err.toString().contains("cannot load the configuration"), err.toString());
  }

  /** The thesis's step 10: restart in server mode with the saved configuration and test.ppm. */
  @Test
  void servesTheSavedTutorialConfiguration() throws Exception {
    RgbImage scene = TestScene.render();
    Path image = dir.resolve("test.ppm");
    ImageFiles.write(scene, image);
    ChannelBank bank = new ChannelBank();
    Trainer t = new Trainer(bank);
    RgbImage small = scene.scaled(160, 120);
    for (TestScene.Box b : List.of(TestScene.BOOK, TestScene.CUP)) {
      TestScene.Box s = b.scaled(160, 120);
      t.addRect(small, s.x0(), s.y0(), s.x1(), s.y1());
    }
    ChannelLutFile.write(bank.copyOf(1), dir.resolve("channel1.lut"));
    bank.setTrackedBlobs(1, 2);
    ActsConfig.of(bank, 160, 120, 5, 5001).write(dir.resolve("actsconfig"));

    ActsCommand cmd = new ActsCommand();
    CommandLine cl = cli(cmd);
    CompletableFuture<Integer> run =
        CompletableFuture.supplyAsync(
            () ->
                cl.execute(
                    "-t", // ACTS's headless start with a configuration
                    dir.resolve("actsconfig").toString(),
                    "-f",
                    image.toString(),
                    "-p",
                    "0", // and no --bind: this computer only, as the guiServer without a login
                    "-G",
                    "vfw",
                    "-x"));
    assertTrue(cmd.awaitStarted(30, TimeUnit.SECONDS));
    assertNotNull(cmd.server(), "started: " + err);
    String line = out.toString();
    assertTrue(line.contains("ACTS server listening on 127.0.0.1:" + cmd.server().getPort()), line);
    assertTrue(line.contains("channels: 1 (2 blobs)"), line);
    assertTrue(err.toString().contains("-G vfw ignored"), err.toString());
    assertTrue(err.toString().contains("-x (PXC200 grabber)"), err.toString());
    assertTrue(cmd.server().awaitFrames(1, 10, TimeUnit.SECONDS));
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("127.0.0.1", cmd.server().getPort()));
      acts.setReadTimeouts(5000, 5000);
      acts.requestPacket();
      assertTrue(acts.receiveBlobInfo());
      assertEquals(2, acts.getNumBlobs(1));
      ArACTSBlob blob = new ArACTSBlob();
      acts.getBlob(1, 1, blob);
      assertTrue(TestScene.BOOK_EXTENT.scaled(160, 120).contains(blob.getXCG(), blob.getYCG()));
    }
    cmd.requestStop();
    assertEquals(0, run.get(30, TimeUnit.SECONDS));
    assertTrue(out.toString().contains("ACTS server stopped"), out.toString());
  }

  @Test
  void quitRequestStopsTheCommandWhenAllowed() throws Exception {
    Path image = dir.resolve("scene.png");
    ImageFiles.write(TestScene.render(), image);
    Files.writeString(dir.resolve("ACTS.pref"), "Width 80\nHeight 60\n");
    ActsCommand cmd = new ActsCommand();
    CommandLine cl = cli(cmd);
    CompletableFuture<Integer> run =
        CompletableFuture.supplyAsync(
            () ->
                cl.execute(
                    "--prefs",
                    dir.resolve("ACTS.pref").toString(),
                    "-f",
                    image.toString(),
                    "-p",
                    "0",
                    "--bind",
                    "127.0.0.1",
                    "--allow-quit",
                    "-t", // alone: headless, no configuration
                    "-i",
                    "-R",
                    "100"));
    assertTrue(cmd.awaitStarted(30, TimeUnit.SECONDS));
    assertNotNull(cmd.server(), err.toString());
    assertTrue(out.toString().contains("80x60"), out.toString());
    assertTrue(err.toString().contains("-t: this server never shows graphics"), err.toString());
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("127.0.0.1", cmd.server().getPort()));
      acts.requestQuit();
    }
    assertEquals(0, run.get(30, TimeUnit.SECONDS));
  }
}
