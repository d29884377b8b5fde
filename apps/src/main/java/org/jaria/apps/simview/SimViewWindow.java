package org.jaria.apps.simview;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import javafx.animation.AnimationTimer;
import javafx.beans.binding.Bindings;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Scene;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.CheckMenuItem;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;
import javafx.scene.control.ProgressBar;
import javafx.scene.control.Separator;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.ToggleGroup;
import javafx.scene.control.ToolBar;
import javafx.scene.control.Tooltip;
import javafx.scene.input.KeyCombination;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import javafx.stage.Stage;
import javafx.stage.WindowEvent;
import org.jaria.acts.image.ImageSource;
import org.jaria.apps.eztrain.EzTrainOptions;
import org.jaria.apps.eztrain.EzTrainWindow;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppPrefs;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.apps.fx.Prompts;
import org.jaria.apps.fx.ShortcutHelp;
import org.jaria.apps.fx.WindowState;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.camera.SimCamera;
import org.jaria.simvision.SimCameraSource;
import org.jaria.simvision.TrainingScene;

/**
 * The simulator's window: the world drawn live (map, robots with footprints, sonar cones and
 * ranges, laser, camera field of view, true pose against odometry, the coloured objects cameras
 * see), run/pause, step and speed controls, mouse tools to place robots, move obstacles and add
 * boxes, and EZ-Train on a robot's camera (Camera menu).
 *
 * <p>While the world runs, the view takes a {@link org.jaria.sim.SimSnapshot} every frame (the
 * world's thread is never blocked by drawing); while it is paused, it draws after each change.
 */
public final class SimViewWindow implements DesktopApp {

  private static final long MIN_FRAME_NANOS = 1_000_000_000L / 30;
  private static final long PAUSED_FRAME_NANOS = 250_000_000L;

  /** Simulated time one press of Step advances (one SIP cycle), ms. */
  public static final long STEP_MILLIS = 100;

  private final Map<String, Double> speeds = new LinkedHashMap<>();

  private final Stage stage;
  private final AppPrefs prefs;
  private final Prompts prompts;
  private final SimController controller;
  private final boolean ownsWorld;
  private final SimCanvas canvas;
  private final BackgroundWork work = new BackgroundWork("simview-worker");
  private final ToggleButton run = new ToggleButton("Run");
  private final Button step = new Button("Step");
  private final ComboBox<String> speed = new ComboBox<>();
  private final ComboBox<RobotChoice> robot = new ComboBox<>();
  private final Label status = new Label("");
  private final Label clock = new Label("");
  private final CompletableFuture<Void> ready = new CompletableFuture<>();
  private final List<AutoCloseable> closeables = new ArrayList<>();
  private final AppEnvironment env;
  private final List<EzTrainWindow> ezTrains = new ArrayList<>();
  private EzTrainOptions ezTrainOptions = EzTrainOptions.defaults();
  // Draws the world at most 30 times a second while it runs, and never more often than every
  // other frame's drawing time (a big map on a software renderer must not take the whole JavaFX
  // thread); while paused, four times a second picks up changes made from outside (a program
  // adding obstacles), and the view's own changes draw at once.
  private final AnimationTimer timer =
      new AnimationTimer() {
        private long lastFrame;
        private long lastCost;

        @Override
        public void handle(long now) {
          long interval =
              controller.isRunning() ? Math.max(MIN_FRAME_NANOS, 2 * lastCost) : PAUSED_FRAME_NANOS;
          if (now - lastFrame < interval) {
            return;
          }
          long t = System.nanoTime();
          canvas.refresh();
          updateClock();
          lastCost = System.nanoTime() - t;
          lastFrame = now;
        }
      };

  /**
   * Builds the window (JavaFX thread); call {@link #show(boolean)} next.
   *
   * @param world the world to show
   * @param speedup starting speed (1 = real time, 0 = as fast as possible)
   * @param ownsWorld whether closing the window closes the world
   */
  public SimViewWindow(
      Stage stage, AppEnvironment env, SimWorld world, double speedup, boolean ownsWorld) {
    this.stage = stage;
    this.env = env;
    this.prefs = env.prefs();
    this.prompts = env.prompts().apply(stage);
    this.controller = new SimController(world, speedup);
    this.ownsWorld = ownsWorld;
    speeds.put("0.25×", 0.25);
    speeds.put("0.5×", 0.5);
    speeds.put("1× (real time)", 1.0);
    speeds.put("2×", 2.0);
    speeds.put("5×", 5.0);
    speeds.put("10×", 10.0);
    speeds.put("As fast as possible", 0.0);
    canvas = new SimCanvas(controller);
    canvas.setId("sim-view");
    canvas.setStatusSink(status::setText);
    canvas.setChangeListener(this::updateClock);

    run.setId("run");
    run.setTooltip(new Tooltip("Run or pause the simulation (Space)"));
    run.textProperty().bind(Bindings.when(run.selectedProperty()).then("Pause").otherwise("Run"));
    run.setOnAction(e -> setRunning(run.isSelected()));
    step.setId("step");
    step.setTooltip(new Tooltip("Advance a paused simulation by " + STEP_MILLIS + " ms (S)"));
    step.setOnAction(e -> step());
    step.disableProperty().bind(run.selectedProperty());
    speed.setId("speed");
    String initial = labelOf(speedup);
    speed.getItems().addAll(speeds.keySet());
    speed.getSelectionModel().select(initial);
    speed.setOnAction(e -> controller.setSpeedup(speeds.get(speed.getValue())));
    robot.setId("robot");
    robot.setOnAction(e -> canvas.setRobotIndex(selectedRobot()));
    canvas.setRobotsListener(this::showRobots);

    ToggleGroup tools = new ToggleGroup();
    ToggleButton move =
        toolButton(
            "Move",
            "tool-move",
            SimCanvas.Tool.MOVE,
            tools,
            "Drag robots and obstacles; drag empty space to pan");
    toolButton(
        "Place robot",
        "tool-place",
        SimCanvas.Tool.PLACE,
        tools,
        "Click where the selected robot should stand, drag towards where it should face");
    toolButton("Add box", "tool-box", SimCanvas.Tool.BOX, tools, "Drag a rectangle to add a box");
    move.setSelected(true);

    ToolBar bar = new ToolBar(run, step, new Label("Speed"), speed, new Separator());
    tools.getToggles().forEach(t -> bar.getItems().add((ToggleButton) t));
    bar.getItems().addAll(new Label("Robot"), robot, new Separator());
    bar.getItems().addAll(layerBoxes());
    Button fit = new Button("Fit");
    fit.setId("fit");
    fit.setOnAction(e -> canvas.fit());
    bar.getItems().add(fit);

    ProgressBar progress = new ProgressBar();
    progress.setPrefWidth(100);
    progress.visibleProperty().bind(work.busyProperty());
    status.setId("status");
    clock.setId("clock");
    Region spacer = new Region();
    HBox.setHgrow(spacer, Priority.ALWAYS);
    HBox statusBar = new HBox(12, status, spacer, progress, clock);
    statusBar.setAlignment(Pos.CENTER_LEFT);
    statusBar.setPadding(new Insets(3, 8, 3, 8));

    BorderPane root = new BorderPane(canvas);
    root.setTop(new VBox(menus(), bar));
    root.setBottom(statusBar);
    stage.setScene(new Scene(root));
    stage.setTitle("JAria simulator — " + world.getMap().source());
    WindowState.remember(stage, prefs, "window", 1200, 800);
  }

  /** A robot in the Robot list: its number in the world, shown by its name. */
  record RobotChoice(int number, String name) {
    @Override
    public String toString() {
      return name;
    }
  }

  /**
   * Lists {@code robots} in the Robot list, keeping the selected robot if it is still there (else
   * the first): robots come and go while the world runs (a robot factory's robot lives as long as
   * its client).
   */
  private void showRobots(List<SimSnapshot.RobotView> robots) {
    int selected = selectedRobot();
    List<RobotChoice> choices = new ArrayList<>(robots.size());
    RobotChoice keep = null;
    for (SimSnapshot.RobotView r : robots) {
      RobotChoice c = new RobotChoice(r.index(), r.name());
      choices.add(c);
      if (r.index() == selected) {
        keep = c;
      }
    }
    robot.getItems().setAll(choices);
    if (keep == null && !choices.isEmpty()) {
      keep = choices.get(0);
    }
    robot.getSelectionModel().select(keep);
    canvas.setRobotIndex(selectedRobot());
  }

  /** The number of the robot selected in the Robot list, or -1 if there is none. */
  private int selectedRobot() {
    RobotChoice c = robot.getSelectionModel().getSelectedItem();
    return c == null ? -1 : c.number();
  }

  /** The robots in the Robot list, in its order. */
  List<RobotChoice> robotChoices() {
    return List.copyOf(robot.getItems());
  }

  private ToggleButton toolButton(
      String text, String id, SimCanvas.Tool t, ToggleGroup g, String tip) {
    ToggleButton b = new ToggleButton(text);
    b.setId(id);
    b.setToggleGroup(g);
    b.setTooltip(new Tooltip(tip));
    b.setOnAction(
        e -> {
          b.setSelected(true);
          canvas.setTool(t);
        });
    return b;
  }

  private CheckBox[] layerBoxes() {
    SimRenderer.Layers l = canvas.layers();
    CheckBox sonar = new CheckBox("Sonar");
    CheckBox laser = new CheckBox("Laser");
    CheckBox camera = new CheckBox("Camera");
    CheckBox odo = new CheckBox("Odometry");
    sonar.setId("show-sonar");
    laser.setId("show-laser");
    camera.setId("show-camera");
    odo.setId("show-odometry");
    sonar.setSelected(prefs.getBoolean("sonar", l.sonar()));
    laser.setSelected(prefs.getBoolean("laser", l.laser()));
    camera.setSelected(prefs.getBoolean("camera", l.camera()));
    odo.setSelected(prefs.getBoolean("odometry", l.odometry()));
    Runnable apply =
        () -> {
          canvas.setLayers(
              new SimRenderer.Layers(
                  sonar.isSelected(),
                  laser.isSelected(),
                  camera.isSelected(),
                  odo.isSelected(),
                  true));
          prefs.putBoolean("sonar", sonar.isSelected());
          prefs.putBoolean("laser", laser.isSelected());
          prefs.putBoolean("camera", camera.isSelected());
          prefs.putBoolean("odometry", odo.isSelected());
        };
    for (CheckBox c : new CheckBox[] {sonar, laser, camera, odo}) {
      c.setOnAction(e -> apply.run());
    }
    apply.run();
    return new CheckBox[] {sonar, laser, camera, odo};
  }

  private MenuBar menus() {
    MenuItem runItem =
        item(
            "Run / Pause",
            "menu-run",
            "Space",
            () -> {
              run.setSelected(!run.isSelected());
              setRunning(run.isSelected());
            });
    MenuItem stepItem = item("Step " + STEP_MILLIS + " ms", "menu-step", "S", this::step);
    MenuItem quit = item("Close", "menu-close", "Shortcut+W", stage::close);
    Menu sim = new Menu("_Simulation", null, runItem, stepItem, quit);
    MenuItem fit = item("Fit", "menu-fit", "Shortcut+DIGIT0", canvas::fit);
    MenuItem in = item("Zoom In", "menu-zoom-in", "Shortcut+EQUALS", () -> canvas.zoom(1.5));
    MenuItem out = item("Zoom Out", "menu-zoom-out", "Shortcut+MINUS", () -> canvas.zoom(1 / 1.5));
    CheckMenuItem grid = new CheckMenuItem("Grid");
    grid.setSelected(true);
    grid.setOnAction(
        e -> {
          SimRenderer.Layers l = canvas.layers();
          canvas.setLayers(
              new SimRenderer.Layers(
                  l.sonar(), l.laser(), l.camera(), l.odometry(), grid.isSelected()));
        });
    MenuItem train =
        item(
            "Train Colors on the Robot's Camera (EZ-Train)…",
            "menu-eztrain",
            "Shortcut+T",
            this::openEzTrain);
    MenuBar bar =
        new MenuBar(
            sim, new Menu("_View", null, fit, in, out, grid), new Menu("_Camera", null, train));
    bar.getMenus()
        .add(
            new Menu(
                "_Help",
                null,
                item("Keyboard Shortcuts", "menu-keys", "F1", () -> showShortcuts(bar))));
    return bar;
  }

  private void showShortcuts(MenuBar bar) {
    List<String> intro =
        List.of(
            "Mouse on the world",
            "  Wheel              zoom about the pointer",
            "  Right/middle drag  pan (Move tool: also a left drag on empty space)",
            "  Move tool          drag a robot, an obstacle or a colored object",
            "  Place robot tool   press where the robot stands, drag towards where it faces",
            "  Add box tool       drag a rectangle");
    prompts.info("Keyboard shortcuts", ShortcutHelp.text(intro, bar));
  }

  private static MenuItem item(String text, String id, String accel, Runnable action) {
    MenuItem m = new MenuItem(text);
    m.setId(id);
    m.setAccelerator(KeyCombination.keyCombination(accel));
    m.setOnAction(e -> action.run());
    return m;
  }

  private String labelOf(double speedup) {
    for (Map.Entry<String, Double> e : speeds.entrySet()) {
      if (e.getValue() == speedup) {
        return e.getKey();
      }
    }
    String label = String.format(Locale.ROOT, "%s×", speedup);
    speeds.put(label, speedup);
    return label;
  }

  /** Shows the window; runs the world unless {@code paused}. */
  public void show(boolean paused) {
    stage.show();
    canvas.fit();
    timer.start();
    if (!paused) {
      run.setSelected(true);
      setRunning(true);
    }
    canvas.refresh();
    updateClock();
    ready.complete(null);
  }

  /**
   * Compares odometry with the true pose from the robots' poses in {@code start} (e.g. taken when
   * they were added, before the world ran), rather than from when the window opened.
   */
  public void setOdometryStart(SimSnapshot start) {
    canvas.alignOdometry(start);
  }

  /** Zooms to show the map box (x0, y0)-(x1, y1), mm. */
  public void showRegion(double x0, double y0, double x1, double y1) {
    canvas.fitTo(new double[] {x0, y0, x1, y1});
  }

  private void setRunning(boolean on) {
    try {
      if (on) {
        controller.run();
        status.setText("Running");
      } else {
        controller.pause();
        status.setText("Paused");
        canvas.refresh();
      }
    } catch (IllegalStateException e) {
      run.setSelected(controller.isRunning());
      prompts.error("Cannot change the simulation", e.getMessage());
    }
  }

  /** Advances a paused world by {@link #STEP_MILLIS} off the JavaFX thread. */
  public void step() {
    if (controller.isRunning()) {
      status.setText("Pause the simulation to step it");
      return;
    }
    work.submit(
        "Stepping",
        () -> controller.step(STEP_MILLIS),
        e -> prompts.error("Cannot step", e.getMessage()));
    work.submit(
        "Drawing",
        () -> null,
        x -> {
          canvas.refresh();
          updateClock();
        },
        e -> {});
  }

  private void updateClock() {
    SimSnapshot snap = canvas.snapshot();
    clock.setText(
        String.format(
            Locale.ROOT,
            "t = %.1f s   %d robot(s)   %d obstacle(s)   %d client(s)",
            snap.simTimeNanos() / 1e9,
            snap.robots().size(),
            snap.obstacles().size(),
            controller.world().connectedClientCount()));
  }

  // ------------------------------------------------------------------ EZ-Train on a robot's camera

  /** The EZ-Train windows open on this world's cameras. */
  public List<EzTrainWindow> ezTrainWindows() {
    return List.copyOf(ezTrains);
  }

  /** How EZ-Train windows opened from here start (tests give a free port for the ACTS server). */
  public void setEzTrainOptions(EzTrainOptions o) {
    ezTrainOptions = o;
  }

  /**
   * Opens EZ-Train on the selected robot's camera: live video of what a camera on that robot sees
   * in this world, with EZ-Train's ACTS server running, so a program driving the robot here can
   * track the colours being trained. The view draws that camera's field of view.
   *
   * @return the EZ-Train window, or null if there is no robot (the user is told so)
   */
  public EzTrainWindow openEzTrain() {
    int index = selectedRobot();
    if (index < 0) {
      prompts.error(
          "Cannot open EZ-Train",
          "There is no robot in the world to train on: add one, or connect a client to a robot"
              + " factory.");
      return null;
    }
    SimRobot r = controller.world().getRobot(index);
    Stage s = new Stage();
    EzTrainWindow ez =
        new EzTrainWindow(s, env.forApp("eztrain"), ezTrainOptions.withSimCamera(true, -1));
    ez.setSimCameraHook(
        (w, h) -> {
          SimCamera cam = new SimCamera(controller.world(), r, w, h, 100, 450);
          cam.setPanTilt(0, TrainingScene.TILT);
          canvas.attachCamera(index, cam);
          SimCameraSource frames = new SimCameraSource(cam);
          return new ImageSource() {
            @Override
            public int width() {
              return frames.width();
            }

            @Override
            public int height() {
              return frames.height();
            }

            @Override
            public boolean nextFrame(int[] rgb) {
              return frames.nextFrame(rgb);
            }

            @Override
            public String describe() {
              return r.getName() + "'s camera in the simulator";
            }

            @Override
            public void close() {
              canvas.detachCamera(index, cam);
            }
          };
        });
    s.addEventHandler(
        WindowEvent.WINDOW_HIDDEN,
        e -> {
          ez.close();
          ezTrains.remove(ez);
        });
    ezTrains.add(ez);
    s.setTitle("EZ-Train — " + r.getName() + "'s camera");
    ez.show();
    status.setText("EZ-Train on " + r.getName() + "'s camera");
    return ez;
  }

  // ------------------------------------------------------------------ DesktopApp

  @Override
  public Stage stage() {
    return stage;
  }

  @Override
  public CompletableFuture<Void> ready() {
    return ready;
  }

  /** The controller (run, pause, step, place...). */
  public SimController controller() {
    return controller;
  }

  /** The worker that steps the world. */
  public BackgroundWork work() {
    return work;
  }

  SimCanvas canvas() {
    return canvas;
  }

  /** Closes {@code c} (before the world) when the window's app closes. */
  public void closeWith(AutoCloseable c) {
    closeables.add(c);
  }

  @Override
  public void close() {
    for (EzTrainWindow ez : List.copyOf(ezTrains)) {
      ez.stage().hide();
      ez.close();
    }
    ezTrains.clear();
    timer.stop();
    controller.pause();
    work.close();
    for (AutoCloseable c : closeables) {
      try {
        c.close();
      } catch (Exception e) {
        status.setText("Closing: " + e.getMessage());
      }
    }
    closeables.clear();
    if (ownsWorld) {
      controller.world().close();
    }
  }
}
