package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javafx.geometry.Point2D;
import javafx.scene.input.KeyCode;
import javafx.scene.input.MouseButton;
import javafx.stage.Stage;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.RgbImage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppPrefs;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.Mouse;
import org.jaria.apps.fx.ScriptedPrompts;
import org.jaria.apps.fx.TestFiles;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
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

/** The map editor driven like a user: open a real map, draw, save, reload. */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class MapperWindowTest {

  @TempDir Path dir;

  private final ScriptedPrompts prompts = new ScriptedPrompts();
  private Mouse mouse;

  @BeforeEach
  void mouse(FxRobot robot) {
    mouse = new Mouse(robot);
  }

  private MapperWindow window;

  @Start
  void start(Stage stage) {
    window = new MapperWindow(stage, AppEnvironment.scripted(prompts));
  }

  @AfterEach
  void closeWindow() {
    FxRuntime.run(() -> window.stage().hide(), 10);
    window.close();
  }

  private void openAndWait(Path file) throws Exception {
    FxRuntime.run(() -> window.show(file), 10);
    window.ready().get(30, TimeUnit.SECONDS);
    WaitForAsyncUtils.waitForFxEvents();
  }

  private Point2D onMap(double mapX, double mapY) {
    MapView v = window.view();
    return v.localToScreen(v.viewport().toScreenX(mapX), v.viewport().toScreenY(mapY));
  }

  @Test
  void drawForbiddenAreaSaveReloadCompare(FxRobot robot) throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    ArMap original = ArMap.readFile(file);
    List<String> originalLines = Files.readAllLines(file);
    openAndWait(file);
    assertEquals(63311, window.document().content().points().size());

    // Snapping to a 500 mm grid makes the drawn corners exact map coordinates.
    FxRuntime.run(
        () -> {
          window.view().setOptions(window.view().options().withGridSize(500));
          window.view().setSnapping(true);
          window.view().viewport().setScale(0.08);
          window.view().centerOn(6000, 0);
          window.view().paint();
        },
        10);
    mouse.click("#tool-forbidden-area");
    mouse.drag(onMap(4000, 1000), onMap(7500, -2000));
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(window.document().isModified());
    assertEquals("Add forbidden area", window.document().undoName());

    robot.press(KeyCode.CONTROL).type(KeyCode.S).release(KeyCode.CONTROL);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertFalse(window.document().isModified());
    assertTrue(prompts.errors.isEmpty(), () -> prompts.errors.toString());
    // columbia.map's goal inside a forbidden area is there on purpose: a warning in the pane, not
    // an error that stops the save with a question.
    assertEquals(0, prompts.problemLists.size(), prompts.problemLists::toString);
    assertTrue(
        FxRuntime.call(
            () ->
                window.problems().stream()
                    .anyMatch(
                        p -> p.toString().startsWith("Warning: goal 'Inside Forbidden Area'")),
            10),
        "listed as a warning");

    ArMap reloaded = ArMap.readFile(file);
    List<ArMapObject> objects = new ArrayList<>(reloaded.getMapObjects());
    ArMapObject added = objects.remove(objects.size() - 1);
    assertEquals(original.getMapObjects(), objects);
    assertEquals(original.getLines(), reloaded.getLines());
    assertEquals(original.getPoints(), reloaded.getPoints());
    assertEquals(original.getMapInfo(), reloaded.getMapInfo());
    assertEquals(original.getOtherHeaderLines(), reloaded.getOtherHeaderLines());
    assertEquals(ArMapObject.forbiddenArea(4000, -2000, 7500, 1000), added);
    // Every line of the original is still there, in order; one Cairn line was added.
    List<String> saved = Files.readAllLines(file);
    assertEquals(originalLines.size() + 1, saved.size());
    List<String> withoutNew = new ArrayList<>(saved);
    withoutNew.remove(added.toMapLine());
    assertEquals(originalLines, withoutNew);
  }

  @Test
  void unchangedRealMapIsWrittenBackByteForByte(FxRobot robot) throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    Path copy = dir.resolve("copy.map");
    openAndWait(file);
    prompts.files.add(copy);
    mouse.click("#status"); // the window has the keyboard
    robot
        .press(KeyCode.CONTROL, KeyCode.SHIFT)
        .type(KeyCode.S)
        .release(KeyCode.SHIFT, KeyCode.CONTROL);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    assertArrayEquals(Files.readAllBytes(file), Files.readAllBytes(copy));
    assertEquals(ArMap.readFile(file), ArMap.readFile(copy));
  }

  @Test
  void placeGoalThenUndoRedoAndRename(FxRobot robot) throws Exception {
    openAndWait(null);
    mouse.click("#map-view");
    robot.type(KeyCode.G);
    Point2D p = onMap(1000, 2000);
    mouse.click(p, MouseButton.PRIMARY);
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, window.document().content().objects().size());
    ArMapObject goal = window.document().content().objects().get(0).object();
    assertEquals("Goal", goal.type());
    assertEquals("Goal 1", goal.name());
    double pixel = 1 / window.view().viewport().scale();
    assertEquals(1000, goal.pose().x(), 2 * pixel);
    assertEquals(2000, goal.pose().y(), 2 * pixel);

    robot.press(KeyCode.CONTROL).type(KeyCode.Z).release(KeyCode.CONTROL);
    assertTrue(window.document().content().objects().isEmpty());
    robot.press(KeyCode.CONTROL).type(KeyCode.Y).release(KeyCode.CONTROL);
    assertEquals(1, window.document().content().objects().size());

    // Double-click with the select tool renames.
    robot.type(KeyCode.S);
    prompts.texts.add("Charging corner");
    mouse.doubleClick(p);
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals("Charging corner", window.document().content().objects().get(0).object().name());
  }

  @Test
  void selectMoveRotateAndDeleteAnArea(FxRobot robot) throws Exception {
    openAndWait(null);
    FxRuntime.run(
        () -> {
          window
              .document()
              .execute(MapEdits.addObject(ArMapObject.forbiddenArea(0, 0, 4000, 2000)));
          window.view().viewport().setScale(0.05);
          window.view().centerOn(2000, 1000);
          window.view().paint();
        },
        10);
    mouse.click("#tool-select");
    mouse.click(onMap(2000, 1000), MouseButton.PRIMARY);
    assertEquals(1, window.selection().size());

    // Drag the area by its inside 1 m to the right (snapping off: about 1000 mm).
    mouse.drag(onMap(2000, 1000), onMap(3000, 1000));
    WaitForAsyncUtils.waitForFxEvents();
    ArMapObject moved = window.document().content().objects().get(0).object();
    double pixel = 1 / window.view().viewport().scale();
    assertEquals(3000, MapGeometry.center(moved)[0], 2 * pixel);
    assertEquals(1000, MapGeometry.center(moved)[1], 2 * pixel);

    // Rotate with the round handle: drag it to the left of the centre, a quarter turn.
    double[] h = MapRenderer.rotationHandle(window.view().viewport(), moved);
    Point2D handle = window.view().localToScreen(h[0], h[1]);
    double[] c = MapGeometry.center(moved);
    mouse.drag(handle, onMap(c[0] - 3000, c[1]));
    WaitForAsyncUtils.waitForFxEvents();
    ArMapObject turned = window.document().content().objects().get(0).object();
    assertEquals(90, turned.pose().th(), 1.01);
    assertArrayEquals(MapGeometry.areaSize(moved), MapGeometry.areaSize(turned), 1e-6);
    assertEquals("Rotate", window.document().undoName());

    robot.type(KeyCode.DELETE);
    assertTrue(window.document().content().objects().isEmpty());
    robot.press(KeyCode.CONTROL).type(KeyCode.Z).release(KeyCode.CONTROL);
    assertEquals(1, window.document().content().objects().size());
  }

  @Test
  void boxSelectMeasureAndExport(FxRobot robot) throws Exception {
    Path file = TestFiles.columbiaCopy(dir);
    openAndWait(file);
    FxRuntime.run(
        () -> {
          window.view().viewport().setScale(0.05);
          window.view().centerOn(0, 0);
          window.view().paint();
        },
        10);
    mouse.click("#tool-select");
    mouse.drag(onMap(-6000, 3000), onMap(4000, -3000));
    WaitForAsyncUtils.waitForFxEvents();
    assertTrue(window.selection().points().cardinality() > 100);
    assertFalse(window.document().isModified(), "a box selection moves nothing");

    mouse.click("#map-view");
    robot.type(KeyCode.M);
    mouse.drag(onMap(0, 0), onMap(3000, 4000));
    WaitForAsyncUtils.waitForFxEvents();
    MeasureTool m = (MeasureTool) window.view().tool();
    double pixel = 1 / window.view().viewport().scale();
    assertEquals(5000, m.length(), 3 * pixel);
    String status = robot.lookup("#status").queryLabeled().getText();
    assertTrue(status.contains("at 53°"), status);

    Path png = dir.resolve("columbia.png");
    prompts.files.add(png);
    robot.press(KeyCode.CONTROL).type(KeyCode.E).release(KeyCode.CONTROL);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    RgbImage img = ImageFiles.read(png);
    assertTrue(img.height() <= 4000 && img.height() > 2000, () -> img.width() + "x" + img.height());
    int dark = 0;
    for (int p : img.pixels()) {
      dark += (p & 0xFF) < 0x60 ? 1 : 0;
    }
    assertTrue(dark > 20_000, "walls and points are drawn: " + dark);
  }

  @Test
  void openingGarbageShowsTheFileAndLine(FxRobot robot) throws Exception {
    Path bad = dir.resolve("bad.map");
    Files.writeString(bad, "this is not a map\n");
    FxRuntime.run(() -> window.show(bad), 10);
    assertTrue(window.work().awaitIdle(20, TimeUnit.SECONDS));
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, prompts.errors.size());
    assertTrue(prompts.errors.get(0).contains("bad.map:1"), prompts.errors::toString);
    assertTrue(window.ready().isCompletedExceptionally());
  }

  @Test
  void drawEveryKindWithItsKeyThenSaveAndReload(FxRobot robot) throws Exception {
    openAndWait(null);
    FxRuntime.run(
        () -> {
          window.view().setOptions(window.view().options().withGridSize(500));
          window.view().viewport().setScale(0.05);
          window.view().centerOn(5000, 5000);
          window.view().paint();
        },
        10);
    // Snap to Grid from the View menu's shortcut: every drawn end lands on a 500 mm grid point.
    mouse.click("#map-view");
    robot
        .press(KeyCode.CONTROL, KeyCode.SHIFT)
        .type(KeyCode.G)
        .release(KeyCode.SHIFT, KeyCode.CONTROL);
    assertTrue(window.view().isSnapping());

    robot.type(KeyCode.W);
    mouse.drag(onMap(1010, 990), onMap(8990, 1020));
    robot.type(KeyCode.P);
    mouse.click(onMap(3000, 8000), MouseButton.PRIMARY);
    robot.type(KeyCode.F);
    mouse.drag(onMap(6000, 2000), onMap(6000, 6000));
    robot.type(KeyCode.O);
    mouse.drag(onMap(2000, 2000), onMap(2000, 4000));
    robot.type(KeyCode.K);
    mouse.click(onMap(8000, 8000), MouseButton.PRIMARY);
    robot.press(KeyCode.SHIFT).type(KeyCode.G).release(KeyCode.SHIFT);
    mouse.drag(onMap(4000, 4000), onMap(2000, 4000));
    robot.type(KeyCode.G);
    mouse.click(onMap(7000, 3500), MouseButton.PRIMARY);
    WaitForAsyncUtils.waitForFxEvents();

    MapContent c = window.document().content();
    assertEquals(1, c.lines().size());
    assertEquals(new ArLineSegment(1000, 1000, 9000, 1000), c.lines().get(0).segment());
    assertEquals(1, c.points().size());
    assertEquals(3000, c.points().x(0));
    assertEquals(8000, c.points().y(0));
    List<String> types = c.objects().stream().map(e -> e.object().type()).toList();
    assertEquals(List.of("ForbiddenLine", "RobotHome", "Dock", "GoalWithHeading", "Goal"), types);
    ArMapObject line = c.objects().get(0).object();
    assertEquals(new ArLineSegment(6000, 2000, 6000, 6000), line.getFromToSegments().get(0));
    assertEquals(90, c.objects().get(1).object().pose().th(), 1.01, "home faces the drag");
    ArMapObject gh = c.objects().get(3).object();
    assertEquals(4000, gh.pose().x(), 1e-9);
    assertEquals(180, Math.abs(gh.pose().th()), 1.01, "goal with heading faces the drag");
    assertEquals("Goal 1", gh.name());
    assertEquals("Goal 2", c.objects().get(4).object().name());
    assertEquals(7, countUndoSteps());

    Path file = dir.resolve("drawn.map");
    prompts.files.add(file);
    robot.press(KeyCode.CONTROL).type(KeyCode.S).release(KeyCode.CONTROL);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    assertTrue(prompts.errors.isEmpty(), prompts.errors::toString);
    ArMap saved = ArMap.readFile(file);
    assertEquals(c.segments(), saved.getLines());
    assertEquals(c.mapObjects(), saved.getMapObjects());
    assertEquals(c.points(), saved.getPoints());
    assertEquals("drawn.map — JAria Mapper", window.stage().getTitle());
  }

  private int countUndoSteps() {
    return FxRuntime.call(
        () -> {
          int n = 0;
          while (window.document().undo()) {
            n++;
          }
          for (int i = 0; i < n; i++) {
            window.document().redo();
          }
          return n;
        },
        10);
  }

  @Test
  void checkMapListsProblemsSelectsThemAndCanStopTheSave(FxRobot robot) throws Exception {
    openAndWait(null);
    FxRuntime.run(
        () -> {
          window
              .document()
              .execute(MapEdits.addObject(ArMapObject.forbiddenArea(0, 0, 3000, 3000)));
          window.document().execute(MapEdits.addObject(ArMapObject.robotHome("", 1500, 1500, 0)));
          window.document().execute(MapEdits.addLine(new ArLineSegment(6000, 0, 6000, 5000)));
          window.document().execute(MapEdits.addObject(ArMapObject.goal("Wall", 6100, 2000)));
          window.view().fit();
        },
        10);
    mouse.click("#map-view");
    robot.type(KeyCode.F7);
    WaitForAsyncUtils.waitForFxEvents();
    List<MapProblem> found = window.problems();
    assertEquals(2, found.size(), found::toString);
    assertTrue(
        found.get(0).message().startsWith("home at (1500, 1500) is inside a forbidden area"));
    assertTrue(found.get(1).message().contains("100 mm from a wall"), found::toString);
    // Clicking a problem selects the object it is about.
    mouse.click(found.get(1).toString());
    WaitForAsyncUtils.waitForFxEvents();
    long goalId = window.document().content().objects().get(2).id();
    assertEquals(goalId, window.selection().single());

    // Saving asks about the errors; "Cancel" keeps the map unsaved.
    Path file = dir.resolve("checked.map");
    prompts.confirmAnswer = false;
    prompts.files.add(file);
    mouse.click("#map-view");
    robot.press(KeyCode.CONTROL).type(KeyCode.S).release(KeyCode.CONTROL);
    assertTrue(window.work().awaitIdle(30, TimeUnit.SECONDS));
    assertEquals(1, prompts.problemLists.size());
    // The home's problem stops the save; the goal's is a warning, listed in the pane only.
    assertEquals(1, prompts.problemLists.get(0).size(), prompts.problemLists::toString);
    assertFalse(Files.exists(file));
    assertTrue(window.document().isModified());
  }

  @Test
  void objectPanelRenamesAndTurnsTheSelection(FxRobot robot) throws Exception {
    openAndWait(null);
    FxRuntime.run(
        () -> {
          window.document().execute(MapEdits.addObject(ArMapObject.dock("Dock 1", 0, 0, 0)));
          window.selectAndShow(window.document().content().objects().get(0).id());
        },
        10);
    // A click in a short field puts the caret after its text.
    mouse.click("#object-name");
    robot.eraseText(6).write("Charger").type(KeyCode.ENTER);
    mouse.click("#object-heading");
    robot.eraseText(3).write("135").type(KeyCode.ENTER);
    WaitForAsyncUtils.waitForFxEvents();
    ArMapObject o = window.document().content().objects().get(0).object();
    assertEquals("Charger", o.name());
    assertEquals(135, o.pose().th(), 1e-9);
    assertEquals("Rotate", window.document().undoName());
    mouse.click("#object-heading");
    robot.eraseText(5).write("east").type(KeyCode.ENTER);
    WaitForAsyncUtils.waitForFxEvents();
    assertEquals(1, prompts.errors.size());
    assertTrue(prompts.errors.get(0).contains("'east' is not a number"), prompts.errors::toString);
  }

  @Test
  void viewOptionsAndWindowPlaceAreRemembered(FxRobot robot) throws Exception {
    openAndWait(null);
    mouse.click("#map-view");
    robot.type(KeyCode.F1);
    assertEquals(1, prompts.infos.size());
    String keys = prompts.infos.get(0);
    assertTrue(keys.contains("Forbidden area") && keys.contains("Save As"), keys);
    robot.press(KeyCode.CONTROL).type(KeyCode.G).release(KeyCode.CONTROL);
    assertFalse(window.view().options().grid());
    FxRuntime.run(
        () -> {
          window.stage().setWidth(900);
          window.stage().setHeight(650);
          window.stage().setX(40);
          window.stage().setY(30);
          window.stage().hide();
        },
        10);
    window.close();
    AppPrefs prefs = window.prefs();
    window =
        FxRuntime.call(
            () -> {
              MapperWindow again =
                  new MapperWindow(new Stage(), new AppEnvironment(prefs, w -> prompts, true));
              again.show(null);
              return again;
            },
            10);
    WaitForAsyncUtils.waitForFxEvents();
    assertFalse(window.view().options().grid());
    assertEquals(900, window.stage().getWidth(), 1);
    assertEquals(650, window.stage().getHeight(), 1);
    assertEquals(40, window.stage().getX(), 1);
  }
}
