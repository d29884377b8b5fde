package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import javafx.geometry.Point2D;
import javafx.scene.input.KeyCode;
import javafx.scene.input.MouseButton;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.net.arnl.ArnlNavigation;
import org.jaria.net.server.Authenticator;
import org.jaria.net.server.ServerOptions;
import org.jaria.net.server.modes.ArServerModes;
import org.jaria.simguiserver.SimulatedGuiServer;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;
import org.testfx.util.WaitForAsyncUtils;

/**
 * The monitor driven like an operator against a guiServer on the simulator (running at eight times
 * real time, with SonARNL and the simulated camera): it connects and shows the robot, sends the
 * robot to a clicked point and shows it arriving, relocalizes a kidnapped robot by dragging it,
 * drives with the keyboard, edits the configuration, shows the camera, and refuses a wrong password
 * with a clear message. Several monitors watch at once.
 */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class MonitorWindowTest {

  private static final String PASSWORD = "pioneer";
  private static SimulatedGuiServer server;

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private final List<MonitorWindow> windows = new ArrayList<>();
  private Stage stage;

  @BeforeAll
  static void startServer() throws Exception {
    server =
        SimulatedGuiServer.start(
            new SimulatedGuiServer.Options(
                ArMap.loadBundled("office"),
                "office.map",
                "p3dx-sh",
                1,
                ServerOptions.builder()
                    .port(0)
                    .bindAddress("127.0.0.1")
                    .authenticator(Authenticator.sharedSecret(PASSWORD))
                    .build(),
                ArnlNavigation.Mode.THREADED,
                8.0,
                true));
  }

  @AfterAll
  static void stopServer() {
    server.close();
  }

  @Start
  void start(Stage s) {
    stage = s;
  }

  @AfterEach
  void closeWindows() {
    for (MonitorWindow w : windows) {
      FxRuntime.run(
          () -> {
            w.stage().hide();
            w.close();
          },
          10);
    }
  }

  private MonitorWindow open(Stage on, String password) {
    MonitorWindow w =
        FxRuntime.call(
            () -> {
              MonitorWindow m =
                  new MonitorWindow(
                      on,
                      AppEnvironment.scripted(prompts),
                      "127.0.0.1",
                      server.port(),
                      "operator",
                      password);
              on.setWidth(1100);
              on.setHeight(750);
              m.show();
              return m;
            },
            10);
    windows.add(w);
    return w;
  }

  /** A monitor connected with the right password, showing the map and the robot. */
  private MonitorWindow connected() throws Exception {
    MonitorWindow w = open(stage, PASSWORD);
    w.ready().get(20, TimeUnit.SECONDS);
    waitFor(
        "the map and the robot drawn",
        () -> w.canvas().drawnRobot() != null && w.state().map != null);
    return w;
  }

  private static void waitFor(String what, Callable<Boolean> condition) {
    try {
      WaitForAsyncUtils.waitFor(30, TimeUnit.SECONDS, condition);
    } catch (java.util.concurrent.TimeoutException e) {
      throw new AssertionError("not within 30 s: " + what, e);
    }
  }

  /** Where map point (x, y) is on the screen. */
  private static Point2D onMap(MonitorWindow w, double x, double y) {
    return FxRuntime.call(
        () -> {
          MonitorCanvas c = w.canvas();
          return c.localToScreen(c.viewport().toScreenX(x), c.viewport().toScreenY(y));
        },
        10);
  }

  private static double pixelMm(MonitorWindow w) {
    return 1 / FxRuntime.call(() -> w.canvas().viewport().scale(), 10);
  }

  /**
   * Ready (what {@code jaria screenshot monitor} waits for) means the first data are shown: pose,
   * battery and motors are filled in then, not "-", and the information table holds its rows, as
   * tall as they are, with its two columns sharing the width.
   */
  @Test
  void readyMeansTheFirstDataAreShownAndTheTableFitsItsRows() throws Exception {
    MonitorWindow w = open(stage, PASSWORD);
    w.ready().get(20, TimeUnit.SECONDS);
    FxRuntime.run(
        () -> {
          var scene = stage.getScene();
          for (String id : List.of("#status-pose", "#status-battery", "#status-motors")) {
            String text = ((javafx.scene.control.Label) scene.lookup(id)).getText();
            assertTrue(!text.equals("-"), id + " shown: " + text);
          }
          @SuppressWarnings("unchecked")
          javafx.scene.control.TableView<String[]> table =
              (javafx.scene.control.TableView<String[]>) scene.lookup("#info-table");
          int rows = table.getItems().size();
          assertTrue(rows > 0, "the information strings arrived with the rest");
          assertEquals(
              MonitorWindow.infoTableHeight(rows, MonitorWindow.INFO_ROW_HEIGHT),
              table.getMaxHeight(),
              0.5,
              "no empty rows below the " + rows + " rows");
          double header = table.lookup(".column-header-background").getLayoutBounds().getHeight();
          assertTrue(
              header <= MonitorWindow.INFO_HEADER_HEIGHT,
              "the header (" + header + " px) leaves room for every row");
          double columns = table.getColumns().stream().mapToDouble(c -> c.getWidth()).sum();
          assertTrue(
              columns >= table.getWidth() - 4,
              "no empty third column: " + columns + " of " + table.getWidth());
        },
        10);
  }

  @Test
  void severalMonitorsShowTheRobotWhereItIs() throws Exception {
    MonitorWindow a = connected();
    MonitorWindow b = open(FxRuntime.call(Stage::new, 10), PASSWORD);
    b.ready().get(20, TimeUnit.SECONDS);
    for (MonitorWindow w : List.of(a, b)) {
      waitFor(
          "each monitor draws the robot at its pose",
          () -> {
            ArPose shown = w.canvas().drawnRobot();
            return shown != null && shown.findDistanceTo(server.robot().getPose()) < 100;
          });
      assertTrue(w.isConnected());
    }
    waitFor(
        "the information strings count both monitors",
        () ->
            "2"
                .equals(
                    a.state().strings == null ? null : a.state().strings.get("Network clients")));
    assertTrue(a.state().goals.contains("Corridor West"), a.state().goals.toString());
  }

  @Test
  void clickAPointAndWatchTheRobotGetThere(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    ArPose goal = new ArPose(4000, 9500);
    robot.clickOn("#tool-goto");
    robot.clickOn(onMap(w, goal.x(), goal.y()));
    double pixel = pixelMm(w);
    waitFor(
        "the server takes the goal",
        () -> {
          ArPose g = server.nav().getPathPlanningTask().getCurrentGoal();
          return g != null && g.findDistanceTo(goal) < 2 * pixel + 1;
        });
    waitFor(
        "the view shows the robot at the goal",
        () ->
            w.state().path != null
                && w.state().path.state().equals("REACHED_GOAL")
                && w.canvas().drawnRobot().findDistanceTo(goal) < 400);
    assertTrue(server.sim().sim().getTruePose().findDistanceTo(goal) < 600, "really there");
  }

  @Test
  void clickAGoalsMarkerToGoThere(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    robot.clickOn("#tool-goto");
    robot.clickOn(onMap(w, 26000, 9500)); // "Corridor East"
    waitFor(
        "the server plans to the goal by name",
        () -> server.nav().getPathPlanningTask().getStatusString().contains("Corridor East"));
    robot.clickOn("#stop");
    waitFor(
        "stop cancels it",
        () -> "Stop".equals(ArServerModes.of(server.gui().getServer()).getMode()));
  }

  @Test
  void dragTheRobotToWhereItReallyIs(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    ArPose believed = server.robot().getPose();
    ArPose truth = new ArPose(believed.x() + 4000, 9500, believed.th());
    server.sim().sim().setTruePose(truth);
    robot.clickOn("#tool-move");
    Point2D from = onMap(w, believed.x(), believed.y());
    Point2D to = onMap(w, truth.x(), truth.y());
    waitFor(
        "the robot still drawn where it was believed to be",
        () -> w.canvas().drawnRobot().findDistanceTo(believed) < 200);
    robot.drag(from, MouseButton.PRIMARY).dropTo(to);
    waitFor(
        "relocalized where it was dropped",
        () -> server.robot().getPose().findDistanceTo(truth) < 400);
    waitFor(
        "and the view shows it there", () -> w.canvas().drawnRobot().findDistanceTo(truth) < 400);
  }

  @Test
  void arrowKeysDriveTheRobot(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    robot.clickOn("#tool-move");
    robot.clickOn(onMap(w, 15000, 2000)); // focus the map, away from the robot
    robot.press(KeyCode.LEFT);
    try {
      waitFor(
          "the robot turns under teleoperation",
          () ->
              "Drive".equals(ArServerModes.of(server.gui().getServer()).getMode())
                  && Math.abs(server.robot().getRotVel()) > 5);
    } finally {
      robot.release(KeyCode.LEFT);
    }
    robot.press(KeyCode.SPACE).release(KeyCode.SPACE);
    waitFor(
        "space stops it",
        () -> "Stop".equals(ArServerModes.of(server.gui().getServer()).getMode()));
  }

  @Test
  void theConfigurationEditorSetsParametersOnTheRobot(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    robot.clickOn("Configuration");
    waitFor("the configuration shown", () -> w.state().config != null);
    WaitForAsyncUtils.waitForFxEvents();
    int before = server.nav().getLocalizationTask().getParams().getNumSamples();
    int wanted = before == 1500 ? 1600 : 1500;
    assertTrue(
        FxRuntime.call(() -> w.configPane().edit("Localization", "NumSamples", "" + wanted), 10));
    robot.clickOn("#config-apply");
    waitFor(
        "the robot's parameter changed",
        () -> server.nav().getLocalizationTask().getParams().getNumSamples() == wanted);
    waitFor("the editor says so", () -> w.configPane().message().equals("Applied."));
    assertTrue(FxRuntime.call(() -> w.configPane().edit("Localization", "NumSamples", "3"), 10));
    robot.clickOn("#config-apply");
    waitFor("a refusal is shown", () -> w.configPane().message().contains("NumSamples"));
    assertEquals(wanted, server.nav().getLocalizationTask().getParams().getNumSamples());
  }

  @Test
  void theCameraTabShowsTheRobotsCamera(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    robot.clickOn("Camera");
    waitFor("a camera frame shown", () -> w.cameraPane().shownSequence() > 0);
  }

  @Test
  void aServerPopupIsShownAndAnsweredAndTheDrawingsArrive(FxRobot robot) throws Exception {
    MonitorWindow w = connected();
    waitFor(
        "the sonar drawing's points", () -> w.state().drawingPoints.containsKey("sonarCurrent"));
    java.util.concurrent.atomic.AtomicInteger pressed =
        new java.util.concurrent.atomic.AtomicInteger(99);
    org.jaria.net.data.PopupInfo ask =
        new org.jaria.net.data.PopupInfo(
            "",
            "Goal",
            "Carry on to the goal?",
            org.jaria.net.data.PopupInfo.PopupType.QUESTION,
            0,
            1,
            0,
            "",
            "Carry on",
            "Carrying on",
            "Stop here",
            "Stopped",
            "",
            "");
    server.gui().getPopups().createPopup(ask, (id, button) -> pressed.set(button));
    waitFor("the popup is shown", () -> FxRuntime.call(() -> w.popupDialogs().count(), 10) == 1);
    robot.clickOn("Stop here");
    waitFor("the server hears the button", () -> pressed.get() == 1);
    waitFor("the dialog is gone", () -> FxRuntime.call(() -> w.popupDialogs().count(), 10) == 0);
    assertTrue(server.gui().getPopups().getOpenPopups().isEmpty());
  }

  @Test
  void aWrongPasswordIsRefusedWithAClearMessage() {
    MonitorWindow w = open(stage, "pioneeR");
    ExecutionException e =
        org.junit.jupiter.api.Assertions.assertThrows(
            ExecutionException.class, () -> w.ready().get(20, TimeUnit.SECONDS));
    assertEquals("login refused: wrong user name or password", e.getCause().getMessage());
    WaitForAsyncUtils.waitForFxEvents();
    assertFalse(w.isConnected());
    assertEquals(
        "Not connected: login refused: wrong user name or password",
        FxRuntime.call(w::connectionText, 10));
    assertEquals(
        List.of(
            "Cannot connect to 127.0.0.1:"
                + server.port()
                + ": login refused: wrong user name or password"),
        prompts.errors);
  }
}
