package org.jaria.tools.simview;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import javafx.geometry.Point2D;
import javafx.stage.Stage;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimWorld;
import org.jaria.tools.fx.AppEnvironment;
import org.jaria.tools.fx.FxRuntime;
import org.jaria.tools.fx.Mouse;
import org.jaria.tools.fx.ScriptedPrompts;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;

/** The simulator view driven like a user: step it, place a robot, drag an obstacle, run it. */
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
}
