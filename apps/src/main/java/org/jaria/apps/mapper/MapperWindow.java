package org.jaria.apps.mapper;

import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicLong;
import javafx.geometry.Insets;
import javafx.geometry.Pos;
import javafx.scene.Scene;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.ProgressBar;
import javafx.scene.control.SplitPane;
import javafx.scene.control.TitledPane;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyCombination;
import javafx.scene.input.KeyEvent;
import javafx.scene.layout.BorderPane;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import javafx.scene.layout.VBox;
import javafx.stage.Stage;
import org.jaria.apps.fx.AppEnvironment;
import org.jaria.apps.fx.AppPrefs;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.DesktopApp;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Prompts;
import org.jaria.apps.fx.WindowState;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;
import org.jaria.map.MapFormatException;

/**
 * The map editor's main window (a Mapper3-Basic analogue): menus, tool bar, the map view, the
 * selected object's panel, the list of problems and a status bar with a progress indicator for
 * loading and saving, which run off the JavaFX thread.
 */
public final class MapperWindow implements DesktopApp {

  static final List<String> MAP_FILTER =
      List.of("Map files|*.map", "Scan logs (built into a map)|*.2d", "All files|*");

  private final Stage stage;
  private final AppPrefs prefs;
  private final Prompts prompts;
  private final BackgroundWork work = new BackgroundWork("mapper-worker");
  private final MapSelection selection = new MapSelection();
  private final MapDocument[] doc = {MapDocument.newMap()};
  private final MapView view;
  private final ObjectPanel objectPanel;
  private final ListView<MapProblem> problems = new ListView<>();
  private final Label status = new Label("Ready");
  private final Label coords = new Label("");
  private final Label zoom = new Label("");
  private final MapperActions actions;
  private final CompletableFuture<Void> ready = new CompletableFuture<>();
  private final MapValidator validator = new MapValidator();

  /** Builds the window in {@code stage} (JavaFX thread); call {@link #show(Path)} next. */
  public MapperWindow(Stage stage, AppEnvironment env) {
    this.stage = stage;
    this.prefs = env.prefs();
    this.prompts = env.prompts().apply(stage);
    view = new MapView(doc[0], selection);
    view.setId("map-view");
    objectPanel = new ObjectPanel(doc, selection, prompts);
    actions = new MapperActions(this);
    view.setStatusSink(status::setText);
    view.setMouseSink(
        p -> {
          coords.setText(String.format(Locale.ROOT, "x %.0f  y %.0f mm", p[0], p[1]));
          zoom.setText(view.zoomText());
        });
    view.setRenameHandler(this::rename);
    view.addEventHandler(KeyEvent.KEY_PRESSED, this::toolKey);
    loadViewOptions();
    hookDocument(doc[0]);

    problems.setId("problems");
    problems.setPrefHeight(84);
    problems
        .getSelectionModel()
        .selectedItemProperty()
        .addListener(
            (o, was, p) -> {
              if (p != null && p.itemId() >= 0) {
                selectAndShow(p.itemId());
              }
            });
    TitledPane problemPane = new TitledPane("Problems", problems);
    problemPane.setExpanded(true);

    ProgressBar progress = new ProgressBar();
    progress.setId("progress");
    progress.setPrefWidth(140);
    progress.visibleProperty().bind(work.busyProperty());
    progress.progressProperty().bind(work.progressProperty());
    Label busyText = new Label();
    busyText.textProperty().bind(work.messageProperty());
    status.setId("status");
    HBox statusBar = new HBox(12, status, spacer(), busyText, progress, coords, zoom);
    statusBar.setAlignment(Pos.CENTER_LEFT);
    statusBar.setPadding(new Insets(3, 8, 3, 8));

    SplitPane center = new SplitPane(view, objectPanel);
    center.setDividerPositions(0.8);
    SplitPane.setResizableWithParent(objectPanel, false);

    BorderPane root = new BorderPane(center);
    root.setTop(new VBox(actions.menuBar(), actions.toolBar()));
    root.setBottom(new VBox(problemPane, statusBar));
    Scene scene = new Scene(root);
    // Ctrl+Shift+Z redoes too, as in most Linux and Mac programs (the menu shows Ctrl+Y).
    scene
        .getAccelerators()
        .put(KeyCombination.keyCombination("Shortcut+Shift+Z"), () -> doc[0].redo());
    stage.setScene(scene);
    stage.setOnCloseRequest(
        e -> {
          if (!confirmDiscard()) {
            e.consume();
          }
        });
    WindowState.remember(stage, prefs, "window", 1100, 760);
    updateTitle();
  }

  private static Region spacer() {
    Region r = new Region();
    HBox.setHgrow(r, Priority.ALWAYS);
    return r;
  }

  /** Shows the window and, if {@code file} is given, opens it. */
  public void show(Path file) {
    showMap(file == null ? null : MapSource.file(file));
  }

  /** Shows the window and, if {@code source} is given, opens it (a file or a bundled map). */
  public void showMap(MapSource source) {
    stage.show();
    view.requestFocus();
    if (source != null && source.file() != null) {
      open(source.file());
    } else if (source != null) {
      openBundled(source.bundledName());
    } else {
      view.fit();
      view.paint();
      ready.complete(null);
    }
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
    work.close();
  }

  // ------------------------------------------------------------------ accessors

  /** The map being edited. */
  public MapDocument document() {
    return doc[0];
  }

  /** The map view. */
  public MapView view() {
    return view;
  }

  /** The selection. */
  public MapSelection selection() {
    return selection;
  }

  /** The background worker (loading, saving). */
  public BackgroundWork work() {
    return work;
  }

  /** The problems found by the last validation. */
  public List<MapProblem> problems() {
    return new ArrayList<>(problems.getItems());
  }

  Prompts prompts() {
    return prompts;
  }

  AppPrefs prefs() {
    return prefs;
  }

  Stage window() {
    return stage;
  }

  void status(String s) {
    status.setText(s);
  }

  // ------------------------------------------------------------------ document lifecycle

  private void hookDocument(MapDocument d) {
    d.addListener(
        () -> {
          if (d != doc[0]) {
            return;
          }
          selection.retainExisting(d.content(), true);
          objectPanel.refresh();
          actions.refresh();
          updateTitle();
          view.redraw();
        });
  }

  private void setDocument(MapDocument d) {
    setDocument(d, null, null);
  }

  /**
   * Shows {@code d}.
   *
   * @param layer an index of its points made off the JavaFX thread, or null to make one here
   * @param found its problems, or null to check it here
   */
  void setDocument(MapDocument d, PointLayer layer, List<MapProblem> found) {
    doc[0] = d;
    view.setUnderlay(null);
    hookDocument(d);
    int res = d.file().resolution();
    view.setOptions(view.options().withPointSize(res > 0 ? res : 20));
    if (layer != null) {
      view.usePoints(d.content().points(), layer);
    }
    view.setDocument(d);
    objectPanel.refresh();
    actions.refresh();
    problems
        .getItems()
        .setAll(found != null ? found : validator.validate(d.content(), view.points()));
    updateTitle();
    view.paint();
  }

  private void updateTitle() {
    stage.setTitle((doc[0].isModified() ? "*" : "") + doc[0].title() + " — JAria Mapper");
  }

  /** Starts a new, empty map (after asking about unsaved changes). */
  public void newMap() {
    if (confirmDiscard()) {
      setDocument(MapDocument.newMap());
    }
  }

  /** A map read, indexed and checked off the JavaFX thread. */
  private record Opened(MapDocument doc, PointLayer layer, List<MapProblem> problems) {}

  /**
   * Opens a map file on the worker thread (reading, indexing its points and checking it, which
   * takes a moment for a big map); the window stays usable meanwhile and the status bar shows a
   * progress indicator.
   */
  public void open(Path file) {
    if (ScanLogOpener.isScanLog(file)) {
      ScanLogOpener.open(this, file);
      return;
    }
    status("Opening " + file);
    work.submit(
        "Opening " + file.getFileName(),
        () -> {
          AtomicLong ids = new AtomicLong(1);
          MapFile.Loaded l = MapFile.read(file, ids::getAndIncrement);
          MapDocument d = new MapDocument(l, file, ids);
          ArMapPoints p = l.content().points();
          PointLayer layer = new PointLayer(p.xArray(), p.yArray());
          return new Opened(d, layer, validator.validate(l.content(), layer));
        },
        o -> {
          MapDocument d = o.doc();
          setDocument(d, o.layer(), o.problems());
          prefs.put("lastDir", String.valueOf(file.toAbsolutePath().getParent()));
          MapContent c = d.content();
          status(
              String.format(
                  Locale.ROOT,
                  "Opened %s: %d points, %d lines, %d objects",
                  file.getFileName(),
                  c.points().size(),
                  c.lines().size(),
                  c.objects().size()));
          ready.complete(null);
        },
        e -> {
          prompts.error("Cannot open map", openError(file, e));
          ready.completeExceptionally(e);
        });
  }

  /**
   * Opens one of JAria's bundled maps ({@link ArMap#BUNDLED_MAPS}) as a new, unsaved document: Save
   * asks where to write it, so the copy inside JAria stays as it is.
   */
  public void openBundled(String name) {
    status("Opening the bundled map " + name);
    work.submit(
        "Opening " + name,
        () -> {
          AtomicLong ids = new AtomicLong(1);
          MapFile.Loaded l = MapFile.wrap(ArMap.loadBundled(name), ids::getAndIncrement);
          MapDocument d = new MapDocument(l, null, ids, name);
          ArMapPoints p = l.content().points();
          PointLayer layer = new PointLayer(p.xArray(), p.yArray());
          return new Opened(d, layer, validator.validate(l.content(), layer));
        },
        o -> {
          setDocument(o.doc(), o.layer(), o.problems());
          MapContent c = o.doc().content();
          status(
              String.format(
                  Locale.ROOT,
                  "Opened the bundled map %s: %d points, %d lines, %d objects (Save asks where to"
                      + " write it)",
                  name,
                  c.points().size(),
                  c.lines().size(),
                  c.objects().size()));
          ready.complete(null);
        },
        e -> {
          prompts.error("Cannot open map", e.getMessage());
          ready.completeExceptionally(e);
        });
  }

  static String openError(Path file, Exception e) {
    if (e instanceof MapFormatException) {
      return e.getMessage()
          + "\n\nThe file is not a map this editor understands. Open it in a text editor to fix"
          + " the line named above, or choose another file.";
    }
    if (e instanceof NoSuchFileException) {
      return file + " does not exist. Check the name, or choose the file with File → Open.";
    }
    return "Reading " + file + " failed: " + e.getMessage() + "\n\nCheck the file's permissions.";
  }

  /** Saves to the current file, or asks for one. Returns false if nothing was started. */
  public boolean save() {
    Optional<Path> p = doc[0].path();
    if (p.isEmpty()) {
      return saveAs();
    }
    return saveTo(p.get());
  }

  /** Asks for a file and saves there. */
  public boolean saveAs() {
    Optional<Path> p =
        prompts.chooseSaveFile("Save map", MAP_FILTER, lastDir(), doc[0].title() + ".map");
    return p.isPresent() && saveTo(p.get());
  }

  Path lastDir() {
    String d = prefs.get("lastDir", null);
    return d == null ? null : Path.of(d);
  }

  /**
   * Validates the map (asking whether to go on if there are errors) and saves it to {@code file} on
   * the worker thread.
   *
   * @return false if the user chose not to save
   */
  public boolean saveTo(Path file) {
    List<MapProblem> found = validate();
    List<String> errors = new ArrayList<>();
    for (MapProblem p : found) {
      if (p.severity() == MapProblem.Severity.ERROR) {
        errors.add(p.toString());
      }
    }
    if (!errors.isEmpty()
        && !prompts.confirmProblems(
            "Check the map",
            errors.size() + " problem(s) will stop a robot from using this map as intended:",
            errors,
            "Save anyway")) {
      status("Not saved");
      return false;
    }
    MapDocument d = doc[0];
    MapContent content = d.content();
    long mark = d.saveMark();
    MapFile f = d.file();
    work.submit(
        "Saving " + file.getFileName(),
        () -> {
          f.save(content, file);
          return file;
        },
        saved -> {
          d.markSaved(mark, saved);
          prefs.put("lastDir", String.valueOf(saved.toAbsolutePath().getParent()));
          status("Saved " + saved);
        },
        e ->
            prompts.error(
                "Cannot save map",
                "Writing "
                    + file
                    + " failed: "
                    + e.getMessage()
                    + "\n\nThe file on disk is unchanged. Check that the folder exists and is"
                    + " writable, or use File → Save As to choose another place."));
    return true;
  }

  /** Checks the map and lists the problems; returns them. */
  public List<MapProblem> validate() {
    List<MapProblem> found = validator.validate(doc[0].content(), view.points());
    problems.getItems().setAll(found);
    status(found.isEmpty() ? "No problems found" : found.size() + " problem(s) found");
    return found;
  }

  /** Asks before throwing away unsaved changes; true to go ahead. */
  boolean confirmDiscard() {
    return !doc[0].isModified()
        || prompts.confirm(
            "Unsaved changes",
            doc[0].title()
                + " has unsaved changes. Discard them? (Cancel, then File → Save, keeps"
                + " them.)");
  }

  // ------------------------------------------------------------------ editing helpers

  /** Asks for a new name of object {@code id}. */
  public void rename(long id) {
    Optional<MapObjectEntry> e = doc[0].content().findObject(id);
    if (e.isEmpty()) {
      status("Only objects (goals, home, docks, forbidden lines and areas) have names");
      return;
    }
    ArMapObject o = e.get().object();
    Optional<String> name =
        prompts.askText("Rename", "New name of the " + ObjectKind.describe(o.type()), o.name());
    if (name.isPresent() && !name.get().equals(o.name())) {
      try {
        doc[0].execute(MapEdits.replace("Rename", id, MapGeometry.renamed(o, name.get())));
      } catch (IllegalArgumentException ex) {
        prompts.error("Cannot rename", ex.getMessage() + "\n\nChoose a name without quotes.");
      }
    }
  }

  /** Selects item {@code id} and centres the view on it. */
  public void selectAndShow(long id) {
    selection.set(Set.of(id), new BitSet());
    doc[0]
        .content()
        .findObject(id)
        .ifPresent(
            o -> {
              double[] c = MapGeometry.center(o.object());
              view.centerOn(c[0], c[1]);
            });
  }

  private void toolKey(KeyEvent e) {
    if (e.isShortcutDown() || e.isAltDown()) {
      return;
    }
    if (e.getCode() == KeyCode.DELETE || e.getCode() == KeyCode.BACK_SPACE) {
      actions.deleteSelection();
      e.consume();
      return;
    }
    if (actions.selectToolByKey(e.getCode(), e.isShiftDown())) {
      e.consume();
    }
  }

  private void loadViewOptions() {
    RenderOptions o = RenderOptions.DEFAULT;
    view.setOptions(
        o.withGrid(prefs.getBoolean("grid", true))
            .withGridSize(prefs.getDouble("gridSize", 1000))
            .withPoints(prefs.getBoolean("points", true))
            .withLines(prefs.getBoolean("lines", true))
            .withLabels(prefs.getBoolean("labels", true)));
    view.setSnapping(prefs.getBoolean("snap", false));
  }

  void saveViewOptions() {
    RenderOptions o = view.options();
    prefs.putBoolean("grid", o.grid());
    prefs.putDouble("gridSize", o.gridSize());
    prefs.putBoolean("points", o.points());
    prefs.putBoolean("lines", o.lines());
    prefs.putBoolean("labels", o.labels());
    prefs.putBoolean("snap", view.isSnapping());
  }
}
