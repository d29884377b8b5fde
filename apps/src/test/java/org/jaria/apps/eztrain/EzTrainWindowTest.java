package org.jaria.apps.eztrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import javafx.geometry.Point2D;
import javafx.scene.Node;
import javafx.scene.control.Labeled;
import javafx.scene.control.ToggleButton;
import javafx.scene.input.KeyCode;
import javafx.scene.input.MouseButton;
import javafx.scene.text.Text;
import javafx.stage.Stage;
import org.jaria.acts.ArACTSBlob;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.acts.blob.Blob;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelLutFile;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.PlaneLimits;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.Mouse;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.apps.fx.TestImages;
import org.jaria.geom.ArPose;
import org.jaria.simvision.TrainingScene;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;

/**
 * EZ-Train driven like the thesis's tutorial (§5.3.12): load the tutorial image, select channel 1,
 * drag a rectangle over the red book, look at the Thresh view and the blob stats, save the channel
 * and load it again; a robot program sees the blobs through the ACTS server meanwhile.
 */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class EzTrainWindowTest {

  @TempDir Path dir;

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private Mouse mouse;

  @BeforeEach
  void mouse(FxRobot robot) {
    mouse = new Mouse(robot);
  }

  private EzTrainWindow window;

  @Start
  void start(Stage stage) {
    EzTrainOptions o =
        EzTrainOptions.defaults().withPort(0).withBaseDir(dir).withSimCamera(false, 0);
    window = new EzTrainWindow(stage, AppEnvironment.scripted(prompts), o);
    window.show();
  }

  @AfterEach
  void close() {
    FxRuntime.run(() -> window.stage().hide(), 10);
    window.close();
  }

  /** The first image is shown and laid out (the training image has its size and place). */
  private void awaitReady() throws Exception {
    window.ready().get(20, TimeUnit.SECONDS);
    WaitForAsyncUtils.waitForFxEvents();
  }

  private void settle() throws Exception {
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS), "worker idle");
    window.refresh().get(20, TimeUnit.SECONDS);
    WaitForAsyncUtils.waitForFxEvents();
  }

  private static String read(Path p) {
    try {
      return Files.readString(p);
    } catch (IOException e) {
      return e.toString();
    }
  }

  /** Screen point of image pixel (x, y) of the training image. */
  private Point2D pixel(FxRobot robot, int x, int y) {
    Node pane = robot.lookup("#training-image").query();
    int m = 3;
    return pane.localToScreen((x + 0.5) * m, (y + 0.5) * m);
  }

  @Test
  void tutorialTrainThreshStatsSaveReload(FxRobot robot) throws Exception {
    awaitReady();
    Path image = dir.resolve("test.ppm");
    try (InputStream in = getClass().getResourceAsStream(TestScene.PPM_RESOURCE)) {
      Files.copy(in, image);
    }
    // Step 2: File → Load Image.
    prompts.files.add(image);
    mouse.click("File").click("Load Image…");
    settle();
    assertTrue(window.outputText().contains("test.ppm"), window::outputText);

    // Step 3: channel 1 (after visiting channel 2), two blobs tracked.
    mouse.click("#channel-btn-2");
    mouse.click("#channel-btn-1");
    mouse.click("#tracked-blobs .decrement-arrow-button");
    settle();
    assertEquals(1, window.session().channel());
    assertEquals(2, window.session().bank().getTrackedBlobs(1));

    // Step 4: Add, drag a rectangle inside the red book (160x120 coordinates).
    TestScene.Box book = TestScene.BOOK.scaled(160, 120);
    mouse.click("#tool-add");
    mouse.drag(
        pixel(robot, book.x0() + 1, book.y0() + 1), pixel(robot, book.x1() - 1, book.y1() - 1));
    settle();
    assertFalse(window.session().bank().copyOf(1).isEmpty());

    // Step 6: Thresh view with key 2: channel pixels white, the rest black.
    mouse.moveTo(pixel(robot, 80, 20));
    robot.type(KeyCode.DIGIT2);
    settle();
    Rendered r = window.lastRendered();
    assertEquals(ViewMode.THRESH, r.mode());
    int w = r.frame().width();
    int cx = (book.x0() + book.x1()) / 2;
    int cy = (book.y0() + book.y1()) / 2;
    assertEquals(0xFFFFFFFF, r.viewArgb()[cy * w + cx], "book centre is white");
    assertEquals(0xFF000000, r.viewArgb()[5 * w + 5], "background is black");

    // Step 7: Info → Blob stats: the book is the largest blob, inside its extent.
    robot.press(KeyCode.CONTROL).type(KeyCode.B).release(KeyCode.CONTROL);
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(window.outputText().contains("Channel 1: 2 blob(s)"), window::outputText);
    List<Blob> blobs = r.blobs();
    assertEquals(2, blobs.size());
    Blob biggest = blobs.get(0);
    TestScene.Box extent = TestScene.BOOK_EXTENT.scaled(160, 120);
    assertTrue(extent.contains(biggest.xcg(), biggest.ycg()), biggest::toString);
    assertTrue(
        biggest.area() > (book.x1() - book.x0()) * (book.y1() - book.y0()), biggest::toString);

    // A robot program sees the same blobs through the ACTS server.
    assertTrue(window.awaitServerFrames(20_000), "the server tracks frames");
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("localhost", window.serverPort()), acts::getOpenMessage);
      acts.setReadTimeouts(10_000, 10_000); // a loaded machine must not fail the test
      assertTrue(acts.requestPacket(), "request sent");
      assertTrue(acts.receiveBlobInfo(), "reply received");
      assertEquals(2, acts.getNumBlobs(1));
      ArACTSBlob b = new ArACTSBlob();
      assertTrue(acts.getBlob(1, 1, b));
      assertEquals(biggest.area(), b.getArea());
    }

    // Step 8: save the channel (channel1.lut in the working folder).
    mouse.click("#channel-save");
    settle();
    Path lut = dir.resolve("channel1.lut");
    assertTrue(Files.isRegularFile(lut), window::outputText);
    Channel saved = ChannelLutFile.read(lut);
    assertTrue(saved.contentEquals(window.session().bank().copyOf(1)), "saved = trained");

    // Step 9: File → Save Runtime Config lists the channel and its two blobs.
    Path cfg = dir.resolve("actsconfig");
    prompts.files.add(cfg);
    mouse.click("File").click("Save Runtime Config…");
    settle();
    assertTrue(Files.readString(cfg).contains("Channel 1 channel1.lut 2"), () -> read(cfg));

    // Clear the training (confirmed), then load the channel back.
    mouse.click("#clear-training");
    settle();
    assertTrue(window.session().bank().copyOf(1).isEmpty(), "cleared");
    assertTrue(window.lastRendered().blobs().isEmpty(), "no blobs once cleared");
    mouse.click("#channel-load");
    settle();
    assertTrue(window.session().bank().copyOf(1).contentEquals(saved), "loaded = saved");
    assertEquals(blobs, window.lastRendered().blobs());
    assertTrue(prompts.errors.isEmpty(), prompts.errors::toString);
  }

  @Test
  void rightClickCyclesViewsAndUndoRevertsTraining(FxRobot robot) throws Exception {
    awaitReady();
    TestScene.Box cup = TestScene.CUP.scaled(160, 120);
    mouse.drag(pixel(robot, cup.x0(), cup.y0()), pixel(robot, cup.x1(), cup.y1()));
    settle();
    assertFalse(window.session().bank().copyOf(1).isEmpty());
    mouse.click(pixel(robot, 10, 10), MouseButton.SECONDARY);
    settle();
    assertEquals(ViewMode.THRESH, window.lastRendered().mode());
    mouse.click(pixel(robot, 10, 10), MouseButton.SECONDARY);
    settle();
    assertEquals(ViewMode.RAW, window.lastRendered().mode());
    mouse.click("#undo");
    settle();
    assertTrue(window.session().bank().copyOf(1).isEmpty());
    // Pick prints the pixel's colour.
    mouse.click("#tool-pick");
    mouse.click(
        pixel(robot, (cup.x0() + cup.x1()) / 2, (cup.y0() + cup.y1()) / 2), MouseButton.PRIMARY);
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(window.outputText().matches("(?s).*Pick \\(\\d+, \\d+\\): R \\d+ G \\d+ B \\d+.*"));
  }

  @Test
  void manualTrainingPlanesAndSliders(FxRobot robot) throws Exception {
    awaitReady();
    TestScene.Box book = TestScene.BOOK.scaled(160, 120);
    mouse.drag(pixel(robot, book.x0(), book.y0()), pixel(robot, book.x1(), book.y1()));
    settle();
    mouse.click("Manual training");
    settle();
    Rendered r = window.lastRendered();
    assertEquals(3, r.planes().length);
    assertEquals(256, r.planeSize());
    int trained = 0;
    for (int p : r.planes()[0]) {
      trained += p == 0xFFFFFFFF ? 1 : 0;
    }
    assertEquals(window.session().bank().copyOf(1).trainedCells(ColorPlane.RG), trained);

    // High Bright down with the keyboard: dark red stays, nothing bright is left.
    mouse.click("#plane-rg-high");
    for (int i = 0; i < 3; i++) {
      robot.type(KeyCode.LEFT);
    }
    settle();
    PlaneLimits l = window.session().bank().copyOf(1).getLimits(ColorPlane.RG);
    assertTrue(l.highBright() < PlaneLimits.MAX_BRIGHT, l::toString);
    // The first colour-threshold slider up, the Low Bright slider up: both limits are set.
    mouse.click("#plane-rg-first");
    robot.type(KeyCode.RIGHT);
    mouse.click("#plane-rg-low");
    robot.type(KeyCode.RIGHT);
    settle();
    l = window.session().bank().copyOf(1).getLimits(ColorPlane.RG);
    assertTrue(l.firstColor() > 0 && l.lowBright() > 0, l::toString);
    mouse.click("#plane-rg-reset");
    settle();
    assertEquals(PlaneLimits.NONE, window.session().bank().copyOf(1).getLimits(ColorPlane.RG));

    mouse.click("#plane-bg-clear");
    settle();
    assertEquals(0, window.session().bank().copyOf(1).trainedCells(ColorPlane.BG));
    assertTrue(
        window.lastRendered().blobs().isEmpty(), "a channel with an empty plane sees nothing");
    mouse.click("#plane-bg-fill");
    settle();
    assertEquals(256 * 256, window.session().bank().copyOf(1).trainedCells(ColorPlane.BG));
    assertFalse(window.lastRendered().blobs().isEmpty());
  }

  @Test
  void liveVideoFromAnyImageSourceAndSingleFrameGrabs(FxRobot robot) throws Exception {
    awaitReady();
    CountingSource src = new CountingSource(160, 120);
    FxRuntime.run(() -> window.useVideoSource(src), 10);
    assertTrue(src.frames.tryAcquire(3, 10, TimeUnit.SECONDS), "continuous video");
    assertEquals(160, window.session().frame().width());
    mouse.click("#grab-single");
    WaitForAsyncUtils.waitForFxEvents();
    src.frames.drainPermits();
    mouse.click("#grab-frame");
    assertTrue(src.frames.tryAcquire(1, 10, TimeUnit.SECONDS), "one grabbed frame");
    int shade = window.session().frame().get(0, 0) & 0xFF;
    assertEquals(src.count.get() & 0xFF, shade);
    robot.press(KeyCode.CONTROL).type(KeyCode.T).release(KeyCode.CONTROL);
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(window.outputText().contains("frames/s"), window::outputText);
    FxRuntime.run(window::close, 10);
    assertTrue(src.closed.get(), "the source is closed with the window");
  }

  @Test
  void missingCameraAndSimulatorCameraSayWhatToDo(FxRobot robot) throws Exception {
    awaitReady();
    prompts.texts.add(dir.resolve("no-such-camera").toString());
    mouse.click("File").click("Live Video (Camera)…");
    assertTrue(window.work().awaitIdle(20, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, prompts.errors.size(), prompts.errors::toString);
    assertTrue(prompts.errors.get(0).contains("no camera or video file"), prompts.errors::toString);
    assertTrue(prompts.errors.get(0).contains("Load Image"), prompts.errors::toString);
    window.setSimCameraHook(SimCameraHook.NOT_AVAILABLE);
    mouse.click("File").click("Simulator Camera");
    assertTrue(window.work().awaitIdle(20, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(2, prompts.errors.size());
    assertTrue(prompts.errors.get(1).contains("Load Image"), prompts.errors::toString);
  }

  private int[] askActs(int channel) throws Exception {
    assertTrue(window.awaitServerFrames(20_000), "the server tracks frames");
    try (ArACTS_1_2 acts = new ArACTS_1_2()) {
      assertTrue(acts.openPort("localhost", window.serverPort()), acts::getOpenMessage);
      acts.setReadTimeouts(10_000, 10_000);
      assertTrue(acts.requestPacket(), "request sent");
      assertTrue(acts.receiveBlobInfo(), "reply received");
      int n = acts.getNumBlobs(channel);
      if (n == 0) {
        return new int[0];
      }
      ArACTSBlob b = new ArACTSBlob();
      assertTrue(acts.getBlob(channel, 1, b));
      return new int[] {n, b.getXCG(), b.getYCG()};
    }
  }

  @Test
  void simulatorCameraIsLiveVideoARobotProgramCanUse(FxRobot robot) throws Exception {
    awaitReady();
    mouse.click("File").click("Simulator Camera");
    settle();
    TrainingScene scene = window.simulatorScene();
    assertTrue(scene != null && scene.world().isRealTime(), "the simulated world runs");
    int port = scene.robot().getPort();
    assertTrue(window.outputText().contains("listening on TCP port " + port), window::outputText);
    try (Socket s = new Socket("localhost", port)) {
      assertTrue(s.isConnected(), "a robot program can connect to the simulated robot");
    }

    // The camera sees the red ball in front of the robot: train channel 1 on it.
    int[] ball = TestImages.redBox(window.session().frame());
    assertTrue(ball != null, "the red ball is in view");
    int qx = (ball[2] - ball[0]) / 4;
    int qy = (ball[3] - ball[1]) / 4;
    mouse.drag(pixel(robot, ball[0] + qx, ball[1] + qy), pixel(robot, ball[2] - qx, ball[3] - qy));
    settle();
    mouse.moveTo(pixel(robot, 5, 5));
    robot.type(KeyCode.DIGIT2);
    settle();
    List<Blob> blobs = window.lastRendered().blobs();
    assertFalse(blobs.isEmpty(), "the ball is a blob");
    Blob b = blobs.get(0);
    assertTrue(
        b.xcg() >= ball[0] && b.xcg() <= ball[2] && b.ycg() >= ball[1] && b.ycg() <= ball[3],
        b::toString);
    int[] seen = askActs(1);
    assertTrue(seen.length == 3 && Math.abs(seen[1] - b.xcg()) <= 2, Arrays.toString(seen));

    // Turn the robot away (as a program driving it would): the live video loses the ball.
    ArPose p = scene.robot().getTruePose();
    scene.robot().setTruePose(new ArPose(p.x(), p.y(), 180));
    for (int i = 0; i < 200 && TestImages.redBox(window.session().frame()) != null; i++) {
      window.refresh().get(20, TimeUnit.SECONDS);
    }
    assertEquals(null, TestImages.redBox(window.session().frame()), "the ball left the picture");
    assertEquals(0, askActs(1).length, "and the robot program no longer sees it");

    FxRuntime.run(window::close, 10);
    assertFalse(scene.world().isRealTime(), "closing the window stops the simulated world");
  }

  @Test
  void consoleBanksToolKeysColoursBrushMagnificationAndQuit(FxRobot robot) throws Exception {
    awaitReady();
    // Bank 9-16, third button: channel 11.
    mouse.click("#bank-2").click("#channel-btn-3");
    settle();
    assertEquals(11, window.session().channel());
    assertEquals("11", robot.lookup("#channel-btn-3").queryLabeled().getText());
    assertTrue(window.stage().getTitle().contains("channel 11"), window.stage()::getTitle);
    assertEquals("channel11.lut", robot.lookup("#channel-file").queryTextInputControl().getText());

    // Blobs tracked goes up to 10, no further.
    for (int i = 0; i < 9; i++) {
      mouse.click("#tracked-blobs .increment-arrow-button");
    }
    settle();
    assertEquals(10, window.session().bank().getTrackedBlobs(11));

    // Tool keys over the image.
    mouse.moveTo(pixel(robot, 20, 20));
    for (TrainTool t :
        new TrainTool[] {TrainTool.REMOVE, TrainTool.ERASE, TrainTool.PICK, TrainTool.DRAW}) {
      robot.type(t.key());
      String id = "#tool-" + t.name().toLowerCase(Locale.ROOT);
      assertTrue(robot.lookup(id).queryAs(ToggleButton.class).isSelected(), id);
    }

    // Brush 5 × 5 from the menu, then a Draw stroke along the red book trains its colours; an
    // Erase stroke along the same path takes them out again.
    menu(robot, "Settings", "#menu-brush", "#menu-brush-5");
    assertEquals(5, window.trainingPane().brush());
    TestScene.Box book = TestScene.BOOK.scaled(160, 120);
    int y = (book.y0() + book.y1()) / 2;
    mouse.stroke(pixel(robot, book.x0() + 3, y), pixel(robot, book.x1() - 3, y), 2);
    settle();
    assertFalse(window.session().bank().copyOf(11).isEmpty(), "Draw trained channel 11");
    int w = window.session().width();
    robot.type(KeyCode.DIGIT1);
    settle();
    assertEquals(ViewMode.OVERLAY, window.lastRendered().mode());
    assertEquals(
        0xFF000000 | MarkColor.BLUE.rgb(),
        window.lastRendered().viewArgb()[y * w + (book.x0() + book.x1()) / 2]);

    // Thresh colour red: the channel's pixels are painted red in the Overlay view.
    menu(robot, "Settings", "#menu-thresh", "#menu-thresh-red");
    settle();
    assertEquals(
        0xFF000000 | MarkColor.RED.rgb(),
        window.lastRendered().viewArgb()[y * w + (book.x0() + book.x1()) / 2]);
    menu(robot, "Settings", "#menu-draw", "#menu-draw-green");
    assertEquals(MarkColor.GREEN.rgb(), rgbOf(window.trainingPane().drawColor()));

    mouse.moveTo(pixel(robot, 20, 20));
    robot.type(KeyCode.E);
    mouse.stroke(pixel(robot, book.x0() + 3, y), pixel(robot, book.x1() - 3, y), 2);
    settle();
    assertTrue(window.session().bank().copyOf(11).isEmpty(), "Erase along the same path");

    // Magnification 4: the image is 4 × 160 pixels wide.
    mouse.click("#magnification .increment-arrow-button");
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(4, window.trainingPane().magnification());
    assertEquals(640, window.trainingPane().getWidth(), 0.5);

    robot.type(KeyCode.F1);
    assertEquals(1, prompts.infos.size());
    String keys = prompts.infos.get(0);
    assertTrue(keys.contains("Thresh view") && keys.contains("Blob Stats"), keys);

    // Esc asks before quitting with unsaved channels; "Cancel" keeps the window.
    prompts.confirmAnswer = false;
    robot.type(KeyCode.ESCAPE);
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, prompts.confirms.size());
    assertTrue(prompts.confirms.get(0).contains("Channel(s) 11"), prompts.confirms::toString);
    assertTrue(window.stage().isShowing());
  }

  /**
   * Opens a menu path by clicking each shown entry in turn, as a user does: a menu bar title by its
   * text, then entries by their ids ("#menu-brush").
   */
  private void menu(FxRobot robot, String... path) {
    for (String text : path) {
      mouse.click(
          robot
              .lookup(
                  (Node n) ->
                      (text.startsWith("#")
                              ? text.substring(1).equals(n.getId())
                              : (n instanceof Labeled l && text.equals(l.getText()))
                                  || (n instanceof Text t && text.equals(t.getText())))
                          && n.getScene() != null
                          && n.getScene().getWindow() != null
                          && n.getScene().getWindow().isShowing()
                          && n.isVisible())
              .<Node>query());
    }
  }

  private static int rgbOf(javafx.scene.paint.Color c) {
    return ((int) Math.round(c.getRed() * 255) << 16)
        | ((int) Math.round(c.getGreen() * 255) << 8)
        | (int) Math.round(c.getBlue() * 255);
  }

  /** A source whose frames are all one shade that changes every frame. */
  static final class CountingSource implements ImageSource {
    final Semaphore frames = new Semaphore(0);
    final AtomicInteger count = new AtomicInteger();
    final AtomicBoolean closed = new AtomicBoolean();
    private final int w;
    private final int h;

    CountingSource(int w, int h) {
      this.w = w;
      this.h = h;
    }

    @Override
    public int width() {
      return w;
    }

    @Override
    public int height() {
      return h;
    }

    @Override
    public boolean nextFrame(int[] rgb) {
      int n = count.incrementAndGet();
      Arrays.fill(rgb, 0, w * h, n & 0xFF);
      frames.release();
      return true;
    }

    @Override
    public void close() {
      closed.set(true);
    }
  }
}
