package org.jaria.apps.simview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import javafx.geometry.Point2D;
import javafx.scene.Node;
import javafx.scene.input.KeyCode;
import javafx.stage.Stage;
import org.jaria.apps.eztrain.EzTrainOptions;
import org.jaria.apps.eztrain.EzTrainWindow;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.Mouse;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.apps.fx.TestImages;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.camera.SimCamera;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;
import picocli.CommandLine;

/** The simulator view driven like a user: step it, place a robot, drag an obstacle, run it. */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class SimViewWindowTest {

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private Mouse mouse;

  @BeforeEach
  void mouse(FxRobot robot) {
    mouse = new Mouse(robot);
  }

  private SimWorld world;
  private SimViewWindow window;

  @Start
  void start(Stage stage) {
    world = SimWorld.bundled("office", SimOptions.builder().seed(3).build());
    world.addRobot("p3dx-sh");
    world.addRobot("p3at-sh");
    window = new SimViewWindow(stage, AppEnvironment.scripted(prompts), world, 1, true);
    window.show(true);
  }

  @AfterEach
  void close() {
    FxRuntime.run(() -> window.stage().hide(), 10);
    FxRuntime.run(window::close, 10);
  }

  private Point2D onWorld(double x, double y) {
    SimCanvas c = window.canvas();
    return c.localToScreen(c.viewport().toScreenX(x), c.viewport().toScreenY(y));
  }

  @Test
  void stepAdvancesPausedWorld(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    assertFalse(window.controller().isRunning());
    long steps = world.getStepCount();
    long t0 = world.getClock().nanoTime();
    mouse.click("#step");
    mouse.click("#step");
    assertTrue(window.work().awaitIdle(10, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(steps + 2 * SimViewWindow.STEP_MILLIS / 10, world.getStepCount());
    assertEquals(t0 + 2 * SimViewWindow.STEP_MILLIS * 1_000_000, world.getClock().nanoTime());
    assertEquals(world.getClock().nanoTime(), window.canvas().snapshot().simTimeNanos());
  }

  @Test
  void clickToPlaceRobotWithHeading(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    mouse.click("#tool-place");
    mouse.click("#robot").click("p3at-sh_2");
    Point2D at = onWorld(15000, 3000);
    mouse.drag(at, onWorld(15000, 5000));
    WaitForAsyncUtils.waitForFxEvents();
    ArPose p = world.getRobot(1).getTruePose();
    double pixel = 1 / window.canvas().viewport().scale();
    assertEquals(15000, p.x(), 2 * pixel);
    assertEquals(3000, p.y(), 2 * pixel);
    assertEquals(90, p.th(), 3);
    assertEquals(p, window.canvas().snapshot().robots().get(1).truePose());
  }

  @Test
  void dragObstacleMovesItInTheWorld(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    SimObstacle box = world.injectBox(20000, 15000, 1000, 1000, 0);
    FxRuntime.run(window.canvas()::refresh, 10);
    mouse.click("#tool-move");
    mouse.drag(onWorld(20500, 15000), onWorld(22500, 14000));
    WaitForAsyncUtils.waitForFxEvents();
    List<SimObstacle> now = world.getObstacles();
    assertEquals(1, now.size());
    assertTrue(now.get(0).id() != box.id());
    ArLineSegment first = now.get(0).segments().get(0);
    ArLineSegment was = box.segments().get(0);
    double pixel = 1 / window.canvas().viewport().scale();
    assertEquals(was.x1() + 2000, first.x1(), 2 * pixel);
    assertEquals(was.y1() - 1000, first.y1(), 2 * pixel);
    assertTrue(world.castRay(21500, 15000, 0, 600) > 550, "the old place is free");
  }

  @Test
  void runAndPause(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    mouse.click("#run");
    assertTrue(window.controller().isRunning());
    assertTrue(world.isRealTime());
    mouse.click("#run");
    assertFalse(window.controller().isRunning());
    assertFalse(world.isRealTime());
  }

  @Test
  void keyboardRunsPausesAndStepsAndTheSpeedListSetsTheSpeed(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    mouse.click("#sim-view");
    robot.type(KeyCode.SPACE);
    assertTrue(window.controller().isRunning());
    assertEquals("Pause", robot.lookup("#run").queryLabeled().getText());
    robot.type(KeyCode.SPACE);
    assertFalse(window.controller().isRunning());
    assertEquals("Run", robot.lookup("#run").queryLabeled().getText());
    long t0 = world.getClock().nanoTime();
    robot.type(KeyCode.S);
    assertTrue(window.work().awaitIdle(10, TimeUnit.SECONDS));
    assertEquals(t0 + SimViewWindow.STEP_MILLIS * 1_000_000, world.getClock().nanoTime());

    robot.type(KeyCode.F1);
    assertTrue(prompts.infos.get(0).contains("Run / Pause"), prompts.infos::toString);

    mouse.click("#speed").click("10×");
    assertEquals(10, window.controller().speedup());
    mouse.click("#run");
    assertTrue(world.isRealTime());
    mouse.click("#speed").click("As fast as possible");
    assertEquals(0, window.controller().speedup());
    assertTrue(world.isRealTime(), "still running, at the new speed");
    mouse.click("#run");
    assertFalse(world.isRealTime());
  }

  @Test
  void odometryIsLaidOverTheRobotAgainWhenAClientOpensASession() throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    // A first program drives the robot 2 m and leaves; odometry has counted those 2 m.
    try (SimulatedRobot first = SimulatedRobot.connect(world, world.getRobot(0))) {
      first.robot().enableMotors();
      first.robot().setVel(500);
      first.runMillis(4000);
      first.robot().stop();
      first.runMillis(1000);
    }
    FxRuntime.run(window.canvas()::refresh, 10);
    SimSnapshot.RobotView before = window.canvas().snapshot().robots().get(0);
    assertTrue(before.odometryPose().findDistanceTo(before.truePose()) < 50, before::toString);
    // A second program connects: odometry restarts at 0, 0, 0 where the robot now stands, and the
    // view lays it over the robot there (not 2 m back, where the first session began).
    try (SimulatedRobot second = SimulatedRobot.connect(world, world.getRobot(0))) {
      assertTrue(second.robot().isConnected());
      FxRuntime.run(window.canvas()::refresh, 10);
      SimSnapshot.RobotView now = window.canvas().snapshot().robots().get(0);
      assertTrue(now.truePose().findDistanceTo(ArPose.ORIGIN) > 1000, "the robot is not at 0,0");
      assertTrue(now.odometryPose().findDistanceTo(now.truePose()) < 50, now::toString);
    }
  }

  @Test
  void ezTrainOnTheRobotsCameraSeesTheBallUntilTheUserDragsItAway(FxRobot robot) throws Exception {
    window.ready().get(10, TimeUnit.SECONDS);
    world.getRobot(1).setTruePose(new ArPose(25000, 3000, 0)); // out of the camera's way
    ArPose home = world.getRobot(0).getTruePose();
    world
        .coloredObjects()
        .add(ColoredObject.cylinder("ball", home.x() + 1500, home.y(), 250, 250, 0xC81E1E), false);
    FxRuntime.run(
        () -> {
          window.setEzTrainOptions(EzTrainOptions.defaults().withPort(0));
          window
              .canvas()
              .fitTo(
                  new double[] {
                    home.x() - 3000, home.y() - 2000, home.x() + 3000, home.y() + 2000
                  });
        },
        10);
    mouse.click("#sim-view");
    robot.press(KeyCode.CONTROL).type(KeyCode.T).release(KeyCode.CONTROL);
    WaitForAsyncUtils.waitForFxEvents();
    EzTrainWindow ez = window.ezTrainWindows().get(0);
    ez.ready().get(20, TimeUnit.SECONDS);
    assertTrue(ez.stage().isShowing());
    assertTrue(ez.outputText().contains("camera in the simulator"), ez::outputText);
    assertTrue(TestImages.redBox(ez.session().frame()) != null, "the camera sees the ball");
    assertEquals(
        new SimRenderer.CameraView(0, SimCamera.WIDE_FOV), window.canvas().cameraViews().get(0));

    // The user brings the simulator back to the front and drags the ball behind the robot: the
    // live video no longer shows it.
    FxRuntime.run(window.stage()::toFront, 10);
    mouse.click("#tool-move");
    mouse.drag(onWorld(home.x() + 1500, home.y()), onWorld(home.x() - 1500, home.y() + 500));
    WaitForAsyncUtils.waitForFxEvents();
    ColoredObject moved = world.coloredObjects().list().get(0);
    double pixel = 1 / window.canvas().viewport().scale();
    assertEquals(home.x() - 1500, moved.x(), 2 * pixel);
    assertEquals(home.y() + 500, moved.y(), 2 * pixel);
    for (int i = 0; i < 200 && TestImages.redBox(ez.session().frame()) != null; i++) {
      ez.refresh().get(20, TimeUnit.SECONDS);
    }
    assertEquals(null, TestImages.redBox(ez.session().frame()), "the ball left the picture");

    FxRuntime.run(() -> ez.stage().hide(), 10);
    assertTrue(window.canvas().cameraViews().isEmpty(), "closing EZ-Train puts the camera away");
    assertTrue(window.ezTrainWindows().isEmpty());
  }

  @Test
  void theSimviewCommandOpensAViewThatStepsWithItsButton(FxRobot robot) throws Exception {
    SimViewCommand c = new SimViewCommand();
    new CommandLine(c).parseArgs("--map", "hall", "--robots", "2", "--paused", "--no-listen");
    SimViewWindow w =
        (SimViewWindow)
            FxRuntime.call(() -> c.open(new Stage(), AppEnvironment.scripted(prompts)), 20);
    try {
      w.ready().get(10, TimeUnit.SECONDS);
      SimWorld built = w.controller().world();
      assertEquals(2, built.getRobots().size());
      assertFalse(w.controller().isRunning());
      long t0 = built.getClock().nanoTime();
      mouse.click(robot.from(w.stage().getScene().getRoot()).lookup("#step").<Node>query());
      assertTrue(w.work().awaitIdle(10, TimeUnit.SECONDS));
      WaitForAsyncUtils.waitForFxEvents();
      assertEquals(t0 + SimViewWindow.STEP_MILLIS * 1_000_000, built.getClock().nanoTime());
      assertEquals(built.getClock().nanoTime(), w.canvas().snapshot().simTimeNanos());
    } finally {
      FxRuntime.run(
          () -> {
            w.stage().hide();
            w.close();
          },
          10);
    }
  }
}
