package org.jaria.apps.monitor;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicBoolean;
import javafx.animation.AnimationTimer;
import javafx.application.Platform;
import javafx.beans.property.ReadOnlyStringWrapper;
import javafx.collections.FXCollections;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Scene;
import javafx.scene.control.Button;
import javafx.scene.control.CheckBox;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.ProgressIndicator;
import javafx.scene.control.Separator;
import javafx.scene.control.Slider;
import javafx.scene.control.Tab;
import javafx.scene.control.TabPane;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableView;
import javafx.scene.control.TextField;
import javafx.scene.control.TextInputControl;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.ToggleGroup;
import javafx.scene.control.ToolBar;
import javafx.scene.control.Tooltip;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.GridPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.apps.fx.Prompts;
import org.jaria.apps.fx.WindowState;
import org.jaria.geom.ArPose;
import org.jaria.net.client.ArClientBase;
import org.jaria.net.client.ConnectionListener;
import org.jaria.net.data.CommandInfo;
import org.jaria.net.data.InfoStrings;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.RobotUpdate;

/**
 * The robot monitor's window (MobileEyes): the map with the robot, its sonar, the localization's
 * particles and the planned path; tools to send the robot to a point or a goal and to relocalize it
 * by dragging; keyboard teleoperation; the robot's status with the program's information strings;
 * the configuration editor; the camera; the custom commands.
 */
public final class MonitorWindow implements DesktopApp {

  private final Stage stage;
  private final Prompts prompts;
  private final String host;
  private final int port;
  private final String user;
  private final String password;
  private final MonitorState state = new MonitorState();
  private final AtomicBoolean dirty = new AtomicBoolean(true);
  private final GuiServerLink link;
  private final BackgroundWork work = new BackgroundWork("monitor-network");
  private final MonitorCanvas canvas;
  private final TeleopKeys teleop;
  private final ConfigPane configPane;
  private final CameraPane cameraPane = new CameraPane();
  private final PopupDialogs popupDialogs;
  private final ScanControls scanControls;
  private final CompletableFuture<Void> ready = new CompletableFuture<>();

  /** The information table's row height and header height, pixels (Modena's at 12 px). */
  static final double INFO_ROW_HEIGHT = 24;

  static final double INFO_HEADER_HEIGHT = 28; // Modena's is 26 at 12 px; a little room

  /** Connected, and the first data are not all shown yet (JavaFX thread only). */
  private boolean awaitingFirstData;

  private final Button connect = new Button("Connect");
  private final ComboBox<String> goals = new ComboBox<>();
  private final Label connection = new Label("Not connected");
  private final Label modeStatus = new Label("");
  private final Label poseLabel = new Label("-");
  private final Label velLabel = new Label("-");
  private final Label batteryLabel = new Label("-");
  private final Label motorsLabel = new Label("-");
  private final Label locLabel = new Label("-");
  private final Label pathLabel = new Label("-");
  private final TableView<String[]> infoTable = new TableView<>();
  private final ListView<CommandInfo> commands = new ListView<>();
  private final TextField commandArgs = new TextField();
  private final Label commandResult = new Label("");
  private final Tab cameraTab = new Tab("Camera");
  private InfoStrings shownStrings;
  private List<String> shownGoals = List.of();
  private final AnimationTimer timer =
      new AnimationTimer() {
        @Override
        public void handle(long now) {
          if (dirty.getAndSet(false)) {
            refresh();
          }
        }
      };

  /**
   * Builds the window (JavaFX thread); {@link #show()} shows it and connects.
   *
   * @param user user name ("" for a server without login)
   * @param password password (null for none)
   */
  public MonitorWindow(
      Stage stage, AppEnvironment env, String host, int port, String user, String password) {
    this.stage = stage;
    this.prompts = env.prompts().apply(stage);
    this.host = host;
    this.port = port;
    this.user = user == null ? "" : user;
    this.password = password;
    this.link = new GuiServerLink(state, () -> dirty.set(true));
    this.canvas = new MonitorCanvas(state);
    canvas.setId("map");
    canvas.setOnGoto(this::gotoPose);
    canvas.setOnLocalize(this::localize);
    canvas.setOnGotoGoal(g -> send("gotoGoal", g));
    this.teleop =
        new TeleopKeys(
            new TeleopKeys.Sender() {
              @Override
              public void ratioDrive(double trans, double rot, double throttle) {
                send("ratioDrive", trans, rot, throttle);
              }

              @Override
              public void stop() {
                send("stop");
              }
            });
    this.configPane = new ConfigPane(this::applyConfig);
    this.scanControls = new ScanControls(prompts, link::request);
    this.popupDialogs =
        new PopupDialogs(
            stage,
            (id, button) -> {
              java.util.concurrent.CompletableFuture<?> unused = link.popupClicked(id, button);
            });
    link.addConnectionListener(
        new ConnectionListener() {
          @Override
          public void disconnected(ArClientBase client, String reason) {
            Platform.runLater(() -> lostConnection(reason));
          }
        });

    BorderPane root = new BorderPane(canvas);
    root.setTop(toolbar());
    root.setRight(sidePanel());
    root.setBottom(statusBar());
    Scene scene = new Scene(root);
    scene.addEventFilter(KeyEvent.KEY_PRESSED, e -> key(e, true));
    scene.addEventFilter(KeyEvent.KEY_RELEASED, e -> key(e, false));
    stage.focusedProperty().addListener((o, was, is) -> teleop.release());
    stage.setScene(scene);
    stage.setTitle("JAria monitor — " + host + ":" + port);
    WindowState.remember(stage, env.prefs(), "window", 1280, 800);
  }

  private ToolBar toolbar() {
    connect.setId("connect");
    connect.setOnAction(e -> toggleConnection());
    Button stop = new Button("Stop");
    stop.setId("stop");
    stop.setTooltip(new Tooltip("Stop the robot (Space)"));
    stop.setOnAction(e -> send("stop"));
    Button wander = new Button("Wander");
    wander.setId("wander");
    wander.setOnAction(e -> send("wander"));
    ToggleGroup tools = new ToggleGroup();
    ToggleButton move = new ToggleButton("Move");
    move.setId("tool-move");
    move.setTooltip(
        new Tooltip("Drag the map to pan; drag the robot to where it really is to relocalize it"));
    ToggleButton go = new ToggleButton("Go to point");
    go.setId("tool-goto");
    go.setTooltip(
        new Tooltip("Click where the robot should go; drag to say which way it should face"));
    for (ToggleButton b : List.of(move, go)) {
      b.setToggleGroup(tools);
    }
    move.setSelected(true);
    move.setOnAction(
        e -> {
          move.setSelected(true);
          canvas.setTool(MonitorCanvas.Tool.MOVE);
        });
    go.setOnAction(
        e -> {
          go.setSelected(true);
          canvas.setTool(MonitorCanvas.Tool.GOTO);
        });
    goals.setId("goals");
    goals.setPromptText("Goal");
    Button goGoal = new Button("Go");
    goGoal.setId("go-goal");
    goGoal.setOnAction(
        e -> {
          String g = goals.getValue();
          if (g != null) {
            send("gotoGoal", g);
          }
        });
    Button fit = new Button("Fit");
    fit.setId("fit");
    fit.setOnAction(e -> canvas.fit());
    CheckBox sonar = new CheckBox("Sonar");
    CheckBox particles = new CheckBox("Particles");
    CheckBox path = new CheckBox("Path");
    sonar.setId("show-sonar");
    particles.setId("show-particles");
    path.setId("show-path");
    for (CheckBox c : List.of(sonar, particles, path)) {
      c.setSelected(true);
      c.setOnAction(
          e ->
              canvas.setLayers(
                  new MonitorRenderer.Layers(
                      sonar.isSelected(), particles.isSelected(), path.isSelected())));
    }
    Slider speed = new Slider(10, 100, teleop.throttle());
    speed.setId("throttle");
    speed.setPrefWidth(90);
    speed.setTooltip(new Tooltip("Teleoperation speed (arrow keys or W A S D drive)"));
    speed.valueProperty().addListener((o, a, b) -> teleop.setThrottle(b.doubleValue()));
    return new ToolBar(
        connect,
        new Separator(),
        stop,
        wander,
        new Separator(),
        move,
        go,
        new Separator(),
        goals,
        goGoal,
        new Separator(),
        fit,
        sonar,
        particles,
        path,
        new Separator(),
        new Label("Drive speed"),
        speed);
  }

  private TabPane sidePanel() {
    GridPane g = new GridPane();
    g.setHgap(8);
    g.setVgap(4);
    g.setPadding(new Insets(8));
    String[] names = {"Pose", "Velocity", "Battery", "Motors", "Localization", "Path"};
    Label[] values = {poseLabel, velLabel, batteryLabel, motorsLabel, locLabel, pathLabel};
    for (int i = 0; i < names.length; i++) {
      values[i].setId("status-" + names[i].toLowerCase(Locale.ROOT));
      values[i].setWrapText(true);
      Label name = new Label(names[i]);
      name.setMinWidth(Region.USE_PREF_SIZE);
      g.addRow(i, name, values[i]);
    }
    infoTable.setId("info-table");
    TableColumn<String[], String> label = new TableColumn<>("Information");
    label.setCellValueFactory(c -> new ReadOnlyStringWrapper(c.getValue()[0]));
    TableColumn<String[], String> value = new TableColumn<>("Value");
    value.setCellValueFactory(c -> new ReadOnlyStringWrapper(c.getValue()[1]));
    label.setPrefWidth(190);
    value.setPrefWidth(150);
    infoTable.getColumns().add(label);
    infoTable.getColumns().add(value);
    // The two columns share the width (no empty third one), and the table is as tall as its rows
    // (no column of empty ones below them).
    infoTable.setColumnResizePolicy(TableView.CONSTRAINED_RESIZE_POLICY_FLEX_LAST_COLUMN);
    infoTable.setFixedCellSize(INFO_ROW_HEIGHT);
    infoTable.setPlaceholder(new Label("No information strings"));
    fitInfoTable(0);
    VBox status = new VBox(6, g, infoTable);

    commands.setId("commands");
    commands.setCellFactory(
        l ->
            new javafx.scene.control.ListCell<>() {
              @Override
              protected void updateItem(CommandInfo c, boolean empty) {
                super.updateItem(c, empty);
                setText(empty || c == null ? null : c.name() + " — " + c.description());
              }
            });
    commandArgs.setId("command-args");
    commandArgs.setPromptText("arguments, separated by spaces");
    Button run = new Button("Run");
    run.setId("command-run");
    run.setOnAction(e -> runCommand());
    commandResult.setId("command-result");
    commandResult.setWrapText(true);
    HBox runRow = new HBox(6, commandArgs, run);
    HBox.setHgrow(commandArgs, Priority.ALWAYS);
    VBox cmd = new VBox(6, commands, runRow, commandResult);
    cmd.setPadding(new Insets(6));
    VBox.setVgrow(commands, Priority.ALWAYS);

    cameraTab.setContent(cameraPane);
    cameraTab.setId("camera-tab");
    TabPane tabs =
        new TabPane(
            new Tab("Status", status),
            new Tab("Configuration", configPane),
            cameraTab,
            new Tab("Commands", cmd));
    tabs.setId("tabs");
    tabs.setTabClosingPolicy(TabPane.TabClosingPolicy.UNAVAILABLE);
    tabs.setPrefWidth(400);
    cameraTab.setOnSelectionChanged(e -> link.watchVideo(cameraTab.isSelected()));
    return tabs;
  }

  private HBox statusBar() {
    connection.setId("connection");
    modeStatus.setId("mode-status");
    ProgressIndicator busy = new ProgressIndicator();
    busy.setPrefSize(16, 16);
    busy.visibleProperty().bind(work.busyProperty());
    Region spacer = new Region();
    HBox.setHgrow(spacer, Priority.ALWAYS);
    HBox bar = new HBox(12, connection, busy, scanControls.node(), spacer, modeStatus);
    bar.setAlignment(Pos.CENTER_LEFT);
    bar.setPadding(new Insets(3, 8, 3, 8));
    return bar;
  }

  // ------------------------------------------------------------------ connecting

  /** Shows the window and connects. */
  public void show() {
    stage.show();
    timer.start();
    connect();
  }

  private void toggleConnection() {
    if (link.isConnected()) {
      work.submit("Disconnecting", link::disconnect, e -> {});
    } else {
      connect();
    }
  }

  private void connect() {
    connection.setText("Connecting to " + host + ":" + port + "...");
    connect.setDisable(true);
    work.submit(
        "Connecting",
        () -> {
          link.connect(host, port, user, password);
          return link.commands().get();
        },
        list -> {
          connect.setDisable(false);
          connect.setText("Disconnect");
          connection.setText("Connected to " + host + ":" + port);
          commands.setItems(FXCollections.observableArrayList(list));
          cameraPane.setAvailable(link.offers("getVideo"));
          scanControls.setAvailable(link.offers("mappingStart"));
          if (!link.offers("getVideo")) {
            cameraTab.setText("Camera (none)");
          }
          // Ready (for a screenshot) once the first data are shown, not at the connection.
          awaitingFirstData = true;
          dirty.set(true);
        },
        e -> {
          connect.setDisable(false);
          connect.setText("Connect");
          String why = e.getMessage();
          connection.setText("Not connected: " + why);
          prompts.error("Cannot connect to " + host + ":" + port, why);
          ready.completeExceptionally(e);
        });
  }

  private void lostConnection(String reason) {
    connect.setText("Connect");
    connect.setDisable(false);
    connection.setText("Disconnected: " + reason);
    teleop.release();
  }

  // ------------------------------------------------------------------ commands

  private void send(String name, Object... args) {
    if (!link.isConnected()) {
      connection.setText("Not connected: connect first");
      return;
    }
    CompletableFuture<?> unused =
        link.request(name, args)
            .exceptionally(
                e -> {
                  Throwable c = e.getCause() != null ? e.getCause() : e;
                  Platform.runLater(() -> modeStatus.setText(name + " failed: " + c.getMessage()));
                  return null;
                });
  }

  private void gotoPose(ArPose p, boolean useHeading) {
    // ArNetworking's layouts: byte4 x, byte4 y (mm) and, for a heading, byte2 th (degrees).
    if (useHeading) {
      send(
          "gotoPose", (int) Math.round(p.x()), (int) Math.round(p.y()), (short) Math.round(p.th()));
    } else {
      send("gotoPose", (int) Math.round(p.x()), (int) Math.round(p.y()));
    }
  }

  private void localize(ArPose p) {
    // ArNetworking's layout: byte4 x, byte4 y, byte4 th.
    send(
        "localizeToPose",
        (int) Math.round(p.x()),
        (int) Math.round(p.y()),
        (int) Math.round(p.th()));
  }

  private void applyConfig(List<List<String>> changes) {
    CompletableFuture<?> unused =
        link.request("setConfig", setConfigArgs(changes))
            .whenComplete(
                (reply, e) ->
                    Platform.runLater(
                        () -> {
                          if (e != null) {
                            Throwable c = e.getCause() != null ? e.getCause() : e;
                            configPane.applied(List.of("Not applied: " + c.getMessage()));
                          } else {
                            String first = reply.bufToStr();
                            configPane.applied(first.isEmpty() ? List.of() : List.of(first));
                            link.fetchConfig();
                          }
                        }));
  }

  /**
   * ArNetworking's setConfig arguments: pairs of strings (name, value), a pair ("Section", name)
   * before the parameters of each section. {@code changes} holds [section, name, value] rows.
   */
  static Object[] setConfigArgs(List<List<String>> changes) {
    List<Object> args = new java.util.ArrayList<>();
    String section = null;
    for (List<String> c : changes) {
      if (!c.get(0).equals(section)) {
        section = c.get(0);
        args.add("Section");
        args.add(section);
      }
      args.add(c.get(1));
      args.add(c.get(2));
    }
    return args.toArray();
  }

  private void runCommand() {
    CommandInfo c = commands.getSelectionModel().getSelectedItem();
    if (c == null) {
      commandResult.setText("Choose a command first.");
      return;
    }
    String text = commandArgs.getText().strip();
    Object[] args = text.isEmpty() ? new Object[0] : (Object[]) text.split("\\s+");
    commandResult.setText("Running " + c.name() + "...");
    CompletableFuture<?> unused =
        link.request(c.name(), args)
            .whenComplete(
                (reply, e) ->
                    Platform.runLater(
                        () -> {
                          if (e != null) {
                            Throwable x = e.getCause() != null ? e.getCause() : e;
                            commandResult.setText(c.name() + " failed: " + x.getMessage());
                          } else {
                            String r = reply.hasMore() ? reply.bufToStr() : "";
                            commandResult.setText(
                                c.name() + ": " + (r == null || r.isEmpty() ? "done" : r));
                          }
                        }));
  }

  private void key(KeyEvent e, boolean down) {
    if (stage.getScene().getFocusOwner() instanceof TextInputControl || !link.isConnected()) {
      return;
    }
    if (down ? teleop.pressed(e) : teleop.released(e)) {
      e.consume();
    }
  }

  // ------------------------------------------------------------------ drawing

  private void refresh() {
    canvas.redraw();
    RobotUpdate u = state.robot;
    if (u != null) {
      modeStatus.setText(u.mode() + ": " + u.status());
      poseLabel.setText(String.format(Locale.ROOT, "%.0f, %.0f mm, %.0f°", u.x(), u.y(), u.th()));
      velLabel.setText(String.format(Locale.ROOT, "%.0f mm/s, %.0f °/s", u.vel(), u.rotVel()));
      batteryLabel.setText(String.format(Locale.ROOT, "%.1f V", u.batteryVoltage()));
      motorsLabel.setText(
          (u.motorsEnabled() ? "on" : "off")
              + (u.leftStalled() || u.rightStalled() ? ", STALLED" : "")
              + (u.eStop() ? ", E-STOP" : ""));
    }
    LocalizationSnapshot loc = state.localization;
    if (loc != null) {
      locLabel.setText(
          String.format(
              Locale.ROOT,
              "%s, score %.2f, %d particles%s",
              loc.state(),
              loc.score(),
              loc.numSamples(),
              loc.lost() ? ", LOST" : ""));
    }
    PathSnapshot p = state.path;
    if (p != null) {
      pathLabel.setText(p.state() + (p.status().isEmpty() ? "" : ": " + p.status()));
    }
    InfoStrings s = state.strings;
    if (s != null && !s.equals(shownStrings)) {
      shownStrings = s;
      var rows = FXCollections.<String[]>observableArrayList();
      for (int i = 0; i < s.labels().size(); i++) {
        rows.add(new String[] {s.labels().get(i), s.values().get(i)});
      }
      infoTable.setItems(rows);
      fitInfoTable(rows.size());
    }
    List<String> g = state.goals;
    if (!g.equals(shownGoals)) {
      shownGoals = g;
      goals.getItems().setAll(g);
    }
    configPane.show(state.config);
    cameraPane.show(state.video);
    popupDialogs.show(state.popups);
    if (awaitingFirstData && state.firstDataArrived(link::offers)) {
      awaitingFirstData = false;
      ready.complete(null);
    }
  }

  /** Makes the information table exactly as tall as {@code rows} rows (two for its placeholder). */
  private void fitInfoTable(int rows) {
    double h = infoTableHeight(rows, INFO_ROW_HEIGHT);
    infoTable.setMinHeight(h);
    infoTable.setPrefHeight(h);
    infoTable.setMaxHeight(h);
  }

  /** The height of a table of {@code rows} rows: its header, the rows and its border. */
  static double infoTableHeight(int rows, double rowHeight) {
    return INFO_HEADER_HEIGHT + Math.max(2, rows) * rowHeight + 2;
  }

  // ------------------------------------------------------------------ DesktopApp

  @Override
  public Stage stage() {
    return stage;
  }

  /** Completes once connected, exceptionally if the connection failed. */
  @Override
  public CompletableFuture<Void> ready() {
    return ready;
  }

  PopupDialogs popupDialogs() {
    return popupDialogs;
  }

  MonitorCanvas canvas() {
    return canvas;
  }

  ScanControls scanControls() {
    return scanControls;
  }

  MonitorState state() {
    return state;
  }

  ConfigPane configPane() {
    return configPane;
  }

  CameraPane cameraPane() {
    return cameraPane;
  }

  /** Whether the monitor is connected. */
  public boolean isConnected() {
    return link.isConnected();
  }

  /** The connection line of the status bar. */
  public String connectionText() {
    return connection.getText();
  }

  @Override
  public void close() {
    timer.stop();
    teleop.release();
    work.close();
    link.close();
  }
}
