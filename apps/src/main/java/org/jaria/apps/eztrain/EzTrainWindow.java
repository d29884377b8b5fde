package org.jaria.apps.eztrain;

import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import javafx.application.Platform;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Scene;
import javafx.scene.control.Label;
import javafx.scene.control.MenuBar;
import javafx.scene.control.ProgressBar;
import javafx.scene.control.ScrollPane;
import javafx.scene.control.SplitPane;
import javafx.scene.control.Tab;
import javafx.scene.control.TabPane;
import javafx.scene.control.TextArea;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import javafx.scene.layout.StackPane;
import javafx.scene.layout.VBox;
import javafx.scene.paint.Color;
import javafx.stage.Stage;
import org.jaria.acts.blob.TrackerSettings;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ColorPlane;
import org.jaria.acts.color.PlaneLimits;
import org.jaria.acts.image.ImageSource;
import org.jaria.acts.image.TestScene;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppPrefs;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.apps.fx.Prompts;
import org.jaria.apps.fx.ShortcutHelp;
import org.jaria.apps.fx.WindowState;

/**
 * EZ-Train: the ACTS colour trainer's window — console, training image, manual training and the
 * output area — with the ACTS server running meanwhile so robot programs see the channels being
 * trained (thesis §5.3.12–24).
 *
 * <p>Threads: training and file operations run on {@code eztrain-worker} (one at a time, in order;
 * the status bar shows them), tracking and drawing the image on {@code eztrain-view}, live video on
 * {@code eztrain-video}, and the server on its own threads. The window never waits for them.
 */
public final class EzTrainWindow implements DesktopApp {

  static final List<String> IMAGE_FILTER =
      List.of("Images|*.ppm *.pnm *.png *.jpg *.jpeg *.bmp *.gif", "All files|*");
  static final List<String> LUT_FILTER = List.of("Channel files|*.lut", "All files|*");
  static final List<String> CONFIG_FILTER = List.of("All files|*");

  private final Stage stage;
  private final AppPrefs prefs;
  private final Prompts prompts;
  private final EzTrainOptions options;
  private final EzTrainState state = new EzTrainState();
  private final EzTrainSession session;
  private final BackgroundWork work = new BackgroundWork("eztrain-worker");
  private final ViewRefresher refresher;
  private final TrainingPane training;
  private final ConsolePane console;
  private final ManualTrainingPane manual;
  private final Tab manualTab = new Tab("Manual training");
  private final TextArea output = new TextArea();
  private final Label status = new Label("Ready");
  private final Label serverLabel = new Label("");
  private final ActsServerControl server;
  private final CompletableFuture<Void> ready = new CompletableFuture<>();
  private final EzTrainFiles files;
  private SimCameraHook simCamera;
  // What the view thread draws, replaced on the JavaFX thread whenever a setting changes (the view
  // thread must not read JavaFX properties).
  private volatile ViewRefresher.Params viewParams;
  private VideoFeed feed;
  private Rendered last;

  /** Builds the window in {@code stage} (JavaFX thread); call {@link #show()} next. */
  public EzTrainWindow(Stage stage, AppEnvironment env, EzTrainOptions options) {
    this.stage = stage;
    this.prefs = env.prefs();
    this.prompts = env.prompts().apply(stage);
    this.options = options;
    ChannelBank bank = new ChannelBank();
    session = new EzTrainSession(bank, options.width(), options.height(), options.baseDir());
    TrackerSettings settings = TrackerSettings.DEFAULT.withMinBlobSize(options.minBlobSize());
    server =
        new ActsServerControl(
            session, settings, env.interactive() ? options.port() : -1, options.maxFps());
    state.magnification.set(options.magnification());
    state.viewMode.set(options.view());
    state.channel.set(options.channel());
    state.threshColor.set(parseColor(prefs.get("threshColor", "BLUE"), MarkColor.BLUE));
    state.drawColor.set(parseColor(prefs.get("drawColor", "RED"), MarkColor.RED));
    simCamera =
        new SimulatorCamera(
            env.interactive() ? options.simPort() : -1,
            line -> Platform.runLater(() -> print(line)));
    updateViewParams();
    refresher = new ViewRefresher(session, settings, () -> viewParams, this::show);
    training = new TrainingPane(new TrainingListener());
    training.setId("training-image");
    files = new EzTrainFiles(this, state, session, prompts, prefs, options);
    console = new ConsolePane(state, this);
    manual = new ManualTrainingPane(this);
    EzTrainMenus menus = new EzTrainMenus(this, state);
    layout(menus);
    wireState();
  }

  private static MarkColor parseColor(String s, MarkColor def) {
    try {
      return MarkColor.valueOf(s);
    } catch (IllegalArgumentException e) {
      return def;
    }
  }

  private void layout(EzTrainMenus menus) {
    ScrollPane consoleScroll = new ScrollPane(console);
    consoleScroll.setFitToWidth(true);
    ScrollPane manualScroll = new ScrollPane(manual);
    manualScroll.setFitToWidth(true);
    Tab consoleTab = new Tab("Console", consoleScroll);
    manualTab.setContent(manualScroll);
    manualTab.setId("manual-tab");
    TabPane tabs = new TabPane(consoleTab, manualTab);
    tabs.setTabClosingPolicy(TabPane.TabClosingPolicy.UNAVAILABLE);
    tabs.setMinWidth(380);
    manualTab.setOnSelectionChanged(
        e -> {
          updateViewParams();
          refresher.request();
        });

    StackPane imageHolder = new StackPane(training);
    imageHolder.setAlignment(Pos.CENTER);
    imageHolder.setStyle("-fx-background-color: #303030;");
    ScrollPane imageScroll = new ScrollPane(imageHolder);
    imageScroll.setFitToWidth(true);
    imageScroll.setFitToHeight(true);

    SplitPane split = new SplitPane(tabs, imageScroll);
    split.setDividerPositions(0.32);
    SplitPane.setResizableWithParent(tabs, false);

    output.setId("output");
    output.setEditable(false);
    output.setPrefRowCount(7);
    output.setStyle("-fx-font-family: monospace;");

    ProgressBar progress = new ProgressBar();
    progress.setPrefWidth(120);
    progress.visibleProperty().bind(work.busyProperty());
    Label busy = new Label();
    busy.textProperty().bind(work.messageProperty());
    status.setId("status");
    serverLabel.setId("server-status");
    Region spacer = new Region();
    HBox.setHgrow(spacer, Priority.ALWAYS);
    HBox statusBar = new HBox(12, status, spacer, busy, progress, serverLabel);
    statusBar.setAlignment(Pos.CENTER_LEFT);
    statusBar.setPadding(new Insets(3, 8, 3, 8));

    BorderPane root = new BorderPane(split);
    root.setTop(menus.menuBar());
    root.setBottom(new VBox(output, statusBar));
    Scene scene = new Scene(root);
    scene.addEventFilter(KeyEvent.KEY_PRESSED, new EzTrainKeys(state, training, this::quit));
    stage.setScene(scene);
    stage.setOnCloseRequest(
        e -> {
          if (!confirmQuit()) {
            e.consume();
          }
        });
    WindowState.remember(stage, prefs, "window", 1180, 780);
    updateTitle();
  }

  private void updateViewParams() {
    viewParams =
        new ViewRefresher.Params(
            state.channel.get(),
            state.viewMode.get(),
            state.threshColor.get().rgb(),
            manualTab.isSelected());
  }

  private void wireState() {
    state.channel.addListener(
        (o, a, b) -> {
          updateViewParams();
          int c = b.intValue();
          state.trackedBlobs.set(session.bank().getTrackedBlobs(c));
          state.fileName.set(session.bank().getFileName(c));
          submit("Selecting channel " + c, () -> session.selectChannel(c));
          updateTitle();
        });
    state.trackedBlobs.addListener(
        (o, a, b) -> {
          int c = state.channel.get();
          if (session.bank().getTrackedBlobs(c) != b.intValue()) {
            session.bank().setTrackedBlobs(c, b.intValue());
            refresher.request();
          }
        });
    state.viewMode.addListener(
        (o, a, b) -> {
          updateViewParams();
          refresher.request();
          updateTitle();
        });
    state.threshColor.addListener(
        (o, a, b) -> {
          prefs.put("threshColor", b.name());
          updateViewParams();
          refresher.request();
        });
    state.drawColor.addListener(
        (o, a, b) -> {
          prefs.put("drawColor", b.name());
          training.setDrawColor(fxColor(b));
        });
    state.magnification.addListener((o, a, b) -> training.setMagnification(b.intValue()));
    state.tool.addListener((o, a, b) -> training.setTool(b));
    state.brush.addListener(
        (o, a, b) -> {
          training.setBrush(b.intValue());
          int size = b.intValue();
          submit("Brush size", () -> session.setBrushSize(size));
        });
    state.continuous.addListener(
        (o, a, b) -> {
          if (feed != null) {
            feed.setContinuous(b);
          }
        });
    training.setMagnification(state.magnification.get());
    training.setDrawColor(fxColor(state.drawColor.get()));
    state.trackedBlobs.set(session.bank().getTrackedBlobs(state.channel.get()));
    state.fileName.set(session.bank().getFileName(state.channel.get()));
  }

  private static Color fxColor(MarkColor c) {
    return Color.rgb((c.rgb() >> 16) & 0xFF, (c.rgb() >> 8) & 0xFF, c.rgb() & 0xFF);
  }

  /**
   * Shows the window, starts the ACTS server and loads the start-up configuration, image or camera.
   */
  public void show() {
    stage.show();
    server.start(this::print);
    serverLabel.setText(server.describe());
    int c = state.channel.get();
    submit("Selecting channel " + c, () -> session.selectChannel(c));
    if (options.config() != null) {
      files.loadConfig(options.config());
    }
    // The tutorial image at once; a file, camera or the simulator's camera is opened on the
    // worker (a big image or a slow camera must not freeze the window) and replaces it.
    session.setFrame(TestScene.load());
    if (options.device() != null) {
      files.startCamera(options.device());
    } else if (options.simCamera()) {
      files.simulatorCamera();
    } else if (options.image() != null) {
      files.loadImage(options.image());
    } else {
      print(
          "Image desk-scene.ppm (the tutorial image) at "
              + session.width()
              + "x"
              + session.height());
    }
    for (int[] r : options.train()) {
      submit("Training", () -> session.trainRect(true, r[0], r[1], r[2], r[3]));
    }
    // Ready once the start-up work is done and its result is on screen.
    work.submit(
        "Starting",
        () -> null,
        x -> {
          // The chained future only signals readiness; failures are reported by the refresher.
          CompletableFuture<Rendered> unused =
              refresher
                  .refresh()
                  .whenComplete(
                      (r, e) -> {
                        if (options.blobStats()) {
                          blobStats();
                        }
                        ready.complete(null);
                      });
        },
        e -> ready.completeExceptionally(e));
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

  @Override
  public void close() {
    stopFeed();
    server.close();
    refresher.close();
    work.close();
  }

  // ------------------------------------------------------------------ for tests and hooks

  /** The model (channels and frame). */
  public EzTrainSession session() {
    return session;
  }

  /** The worker running training and file operations. */
  public BackgroundWork work() {
    return work;
  }

  /** The ACTS server's port, or -1 if it is not running. */
  public int serverPort() {
    return server.port();
  }

  /**
   * Waits until the ACTS server has tracked frames made after this call (tests: its replies then
   * reflect the training so far). Not on the JavaFX thread.
   *
   * @return false if there is no server or it took longer than {@code timeoutMs}
   */
  public boolean awaitServerFrames(long timeoutMs) throws InterruptedException {
    return server.awaitFreshFrames(timeoutMs);
  }

  /** Asks for the image to be tracked and drawn again; completes once it is on screen. */
  public CompletableFuture<Rendered> refresh() {
    return refresher.refresh();
  }

  /** The last drawn refresh (JavaFX thread). */
  public Rendered lastRendered() {
    return last;
  }

  /** The training image (tests). */
  TrainingPane trainingPane() {
    return training;
  }

  /** The output area's text (JavaFX thread). */
  public String outputText() {
    return output.getText();
  }

  /** Where File → Simulator Camera gets its frames. */
  public void setSimCameraHook(SimCameraHook hook) {
    simCamera = hook;
  }

  SimCameraHook simCameraHook() {
    return simCamera;
  }

  /** The scene behind EZ-Train's own simulator camera, once opened (tests), else null. */
  org.jaria.simvision.TrainingScene simulatorScene() {
    return simCamera instanceof SimulatorCamera c ? c.scene() : null;
  }

  /** Loading and saving images, cameras, channels and configurations. */
  EzTrainFiles files() {
    return files;
  }

  /** The server port to write into a saved runtime configuration. */
  int serverConfiguredPort() {
    return Math.max(0, server.configuredPort());
  }

  /**
   * Trains on live video from any source (a camera, the simulator's camera, a folder of images).
   * Frames are scaled to the working size; the source is closed when another replaces it or the
   * window closes.
   */
  public void useVideoSource(ImageSource source) {
    stopFeed();
    feed =
        new VideoFeed(
            source,
            session,
            refresher::request,
            e ->
                Platform.runLater(
                    () ->
                        prompts.error(
                            "Video stopped",
                            "Reading from "
                                + source.describe()
                                + " failed: "
                                + e.getMessage()
                                + "\n\nCheck the camera's cable and permissions, then choose"
                                + " File → Live Video again, or load a still image.")));
    feed.setContinuous(state.continuous.get());
    print("Live video from " + source.describe());
    status("Live video: " + source.describe());
  }

  void stopFeed() {
    if (feed != null) {
      feed.close();
      feed = null;
    }
  }

  // ------------------------------------------------------------------ refresh results

  private void show(Rendered r) {
    last = r;
    training.setPixels(r.viewArgb(), r.frame().width(), r.frame().height());
    if (manualTab.isSelected()) {
      manual.show(r, session.bank().copyOf(r.channel()));
    }
    console.markTrained(session.bank().activeMask());
  }

  // ------------------------------------------------------------------ actions

  void print(String line) {
    output.appendText((output.getText().isEmpty() ? "" : "\n") + line);
  }

  void status(String s) {
    status.setText(s);
  }

  private void updateTitle() {
    stage.setTitle(
        "EZ-Train — channel "
            + state.channel.get()
            + " — "
            + state.viewMode.get().label()
            + (session.unsavedMask() != 0 ? " (unsaved channels)" : ""));
  }

  /** Runs {@code job} on the worker, then refreshes the image; errors go to a dialog. */
  void submit(String what, Runnable job) {
    work.submit(
        what,
        () -> {
          job.run();
          return null;
        },
        x -> {
          refresher.request();
          updateTitle();
        },
        e -> prompts.error(what + " failed", String.valueOf(e.getMessage())));
  }

  <T> void submitIo(String what, Callable<T> job, Consumer<T> done, String advice) {
    work.submit(
        what,
        job,
        r -> {
          done.accept(r);
          refresher.request();
          updateTitle();
        },
        e -> prompts.error(what + " failed", e.getMessage() + "\n\n" + advice));
  }

  void undo() {
    work.submit(
        "Undo",
        session::undo,
        done -> {
          status(done ? "Undone" : "Nothing to undo on channel " + state.channel.get());
          refresher.request();
        },
        e -> prompts.error("Undo failed", e.getMessage()));
  }

  void clearTraining() {
    int c = state.channel.get();
    if (prompts.confirm("Clear training", "Remove every color from channel " + c + "?")) {
      submit("Clearing channel " + c, session::clearTraining);
    }
  }

  void setPlaneLimits(ColorPlane plane, PlaneLimits limits) {
    submit("Limits", () -> session.setLimits(plane, limits));
  }

  void fillPlane(ColorPlane plane) {
    submit("Fill plane", () -> session.fillPlane(plane));
  }

  void clearPlane(ColorPlane plane) {
    submit("Clear plane", () -> session.clearPlane(plane));
  }

  void grabFrame() {
    if (feed == null) {
      status("Grab frame needs live video (File → Live Video)");
    } else {
      feed.grabFrame();
    }
  }

  // ---- info

  /** Info → Blob stats: the selected channel's tracked blobs in the output area. */
  public void blobStats() {
    Rendered r = last;
    if (r != null) {
      print(EzTrainInfo.blobStats(r, session.bank().getTrackedBlobs(r.channel())));
    }
  }

  /** Info → Timing: tracking time per frame and frame rates. */
  public void timing() {
    Rendered r = last;
    if (r != null) {
      print(
          EzTrainInfo.timing(
              r, feed != null ? feed.framesPerSecond() : Double.NaN, server.timing()));
    }
  }

  // ---- help

  /** Help → Keyboard Shortcuts. */
  void showShortcuts(MenuBar menus) {
    prompts.info("Keyboard shortcuts", ShortcutHelp.text(EzTrainInfo.keysAndMouse(), menus));
  }

  // ---- quitting

  boolean confirmQuit() {
    int unsaved = session.unsavedMask();
    return unsaved == 0
        || prompts.confirm(
            "Unsaved channels",
            "Channel(s) "
                + EzTrainFiles.channelList(unsaved)
                + " have changes that are not saved. Quit anyway? (Cancel, then File → Save"
                + " Channel, keeps them.)");
  }

  void quit() {
    if (confirmQuit()) {
      stage.setOnCloseRequest(null);
      stage.close();
    }
  }

  // ------------------------------------------------------------------ mouse

  private final class TrainingListener implements TrainingPane.Listener {
    @Override
    public void rect(TrainTool tool, int x0, int y0, int x1, int y1) {
      boolean add = tool == TrainTool.ADD;
      submit(
          add ? "Adding colors" : "Removing colors", () -> session.trainRect(add, x0, y0, x1, y1));
    }

    @Override
    public void stroke(TrainTool tool, List<int[]> points) {
      boolean draw = tool == TrainTool.DRAW;
      submit(draw ? "Drawing" : "Erasing", () -> session.stroke(draw, points));
    }

    @Override
    public void pick(int x, int y) {
      print("Pick " + session.pick(x, y));
    }

    @Override
    public void cycleView() {
      state.viewMode.set(state.viewMode.get().next());
    }

    @Override
    public void grabFrame() {
      EzTrainWindow.this.grabFrame();
    }
  }
}
