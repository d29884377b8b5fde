package org.jaria.apps.mapper;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import javafx.application.Platform;
import javafx.scene.control.CheckMenuItem;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;
import javafx.scene.control.RadioMenuItem;
import javafx.scene.control.SeparatorMenuItem;
import javafx.scene.control.ToggleButton;
import javafx.scene.control.ToggleGroup;
import javafx.scene.control.ToolBar;
import javafx.scene.control.Tooltip;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyCombination;
import org.jaria.acts.image.ImageFiles;
import org.jaria.acts.image.RgbImage;
import org.jaria.apps.fx.BackgroundWork;
import org.jaria.apps.fx.ShortcutHelp;

/**
 * The map editor's menus and tool bar, and the actions behind them. Menu shortcuts use the
 * platform's shortcut key (Ctrl, or Cmd on a Mac); the tools have single-letter keys that work
 * while the map has the keyboard focus (shown in the tool tips and the Tools menu).
 */
final class MapperActions {

  /** A tool and its key. */
  private record ToolEntry(String id, MapTool tool, KeyCode key, boolean shift) {}

  private final MapperWindow w;
  private final Map<String, ToolEntry> tools = new LinkedHashMap<>();
  private final Map<String, ToggleButton> toolButtons = new LinkedHashMap<>();
  private final ToggleGroup toolGroup = new ToggleGroup();
  private final MenuItem undo = new MenuItem("Undo");
  private final MenuItem redo = new MenuItem("Redo");
  private final MenuBar menuBar;
  private final ToolBar toolBar;

  MapperActions(MapperWindow w) {
    this.w = w;
    tool("select", new SelectTool(), KeyCode.S, false);
    tool("pan", new PanTool(), KeyCode.H, false);
    tool("wall", new LineTool(false), KeyCode.W, false);
    tool("point", new PointTool(), KeyCode.P, false);
    tool("goal", new PlaceTool(ObjectKind.GOAL), KeyCode.G, false);
    tool("goal-heading", new PlaceTool(ObjectKind.GOAL_WITH_HEADING), KeyCode.G, true);
    tool("home", new PlaceTool(ObjectKind.HOME), KeyCode.O, false);
    tool("dock", new PlaceTool(ObjectKind.DOCK), KeyCode.K, false);
    tool("forbidden-line", new LineTool(true), KeyCode.F, false);
    tool("forbidden-area", new AreaTool(), KeyCode.A, false);
    tool("measure", new MeasureTool(), KeyCode.M, false);
    menuBar = new MenuBar(fileMenu(), editMenu(), viewMenu(), toolsMenu());
    menuBar.getMenus().add(helpMenu());
    toolBar = new ToolBar();
    for (ToolEntry t : tools.values()) {
      ToggleButton b = new ToggleButton(t.tool().name());
      b.setId("tool-" + t.id());
      b.setToggleGroup(toolGroup);
      b.setTooltip(new Tooltip(t.tool().name() + " (" + keyText(t) + ")"));
      b.setOnAction(
          e -> {
            b.setSelected(true);
            select(t.id());
          });
      toolButtons.put(t.id(), b);
      toolBar.getItems().add(b);
    }
    toolButtons.get("select").setSelected(true);
    refresh();
  }

  private void tool(String id, MapTool t, KeyCode key, boolean shift) {
    tools.put(id, new ToolEntry(id, t, key, shift));
  }

  private static String keyText(ToolEntry t) {
    return (t.shift() ? "Shift+" : "") + t.key().getName();
  }

  MenuBar menuBar() {
    return menuBar;
  }

  ToolBar toolBar() {
    return toolBar;
  }

  /** Makes tool {@code id} active ("select", "wall", "forbidden-area"...). */
  void select(String id) {
    ToolEntry t = tools.get(id);
    if (t == null) {
      throw new IllegalArgumentException("no tool " + id);
    }
    w.view().setTool(t.tool());
    toolButtons.get(id).setSelected(true);
  }

  /** Selects the tool whose key this is; false if none. */
  boolean selectToolByKey(KeyCode key, boolean shift) {
    for (ToolEntry t : tools.values()) {
      if (t.key() == key && t.shift() == shift) {
        select(t.id());
        return true;
      }
    }
    return false;
  }

  /** Updates Undo/Redo texts and enabled states. */
  void refresh() {
    MapDocument d = w.document();
    undo.setText(d.canUndo() ? "Undo " + d.undoName() : "Undo");
    redo.setText(d.canRedo() ? "Redo " + d.redoName() : "Redo");
    undo.setDisable(!d.canUndo());
    redo.setDisable(!d.canRedo());
  }

  private static MenuItem item(String text, String id, String accel, Runnable action) {
    MenuItem m = new MenuItem(text);
    m.setId(id);
    if (accel != null) {
      m.setAccelerator(KeyCombination.keyCombination(accel));
    }
    m.setOnAction(e -> action.run());
    return m;
  }

  private Menu fileMenu() {
    return new Menu(
        "_File",
        null,
        item("New", "menu-new", "Shortcut+N", w::newMap),
        item("Open…", "menu-open", "Shortcut+O", this::openDialog),
        item("Save", "menu-save", "Shortcut+S", w::save),
        item("Save As…", "menu-save-as", "Shortcut+Shift+S", w::saveAs),
        new SeparatorMenuItem(),
        item("Export PNG…", "menu-export", "Shortcut+E", this::exportDialog),
        new SeparatorMenuItem(),
        item("Quit", "menu-quit", "Shortcut+Q", this::quit));
  }

  private Menu editMenu() {
    undo.setId("menu-undo");
    undo.setAccelerator(KeyCombination.keyCombination("Shortcut+Z"));
    undo.setOnAction(e -> w.document().undo());
    redo.setId("menu-redo");
    redo.setAccelerator(KeyCombination.keyCombination("Shortcut+Y"));
    redo.setOnAction(e -> w.document().redo());
    return new Menu(
        "_Edit",
        null,
        undo,
        redo,
        new SeparatorMenuItem(),
        item("Delete  (Del)", "menu-delete", null, this::deleteSelection),
        item("Select All", "menu-select-all", "Shortcut+A", this::selectAll),
        item("Rename…", "menu-rename", "F2", this::renameSelection),
        item("Rotate…", "menu-rotate", "Shortcut+R", this::rotateSelection),
        new SeparatorMenuItem(),
        item("Check Map", "menu-validate", "F7", w::validate));
  }

  private Menu viewMenu() {
    CheckMenuItem grid = check("Grid", "menu-grid", "Shortcut+G", w.view().options().grid());
    grid.setOnAction(e -> setOptions(w.view().options().withGrid(grid.isSelected())));
    CheckMenuItem snap =
        check("Snap to Grid", "menu-snap", "Shortcut+Shift+G", w.view().isSnapping());
    snap.setOnAction(
        e -> {
          w.view().setSnapping(snap.isSelected());
          w.saveViewOptions();
        });
    Menu size = new Menu("Grid Size");
    ToggleGroup g = new ToggleGroup();
    for (int mm : new int[] {50, 100, 250, 500, 1000, 5000}) {
      RadioMenuItem r = new RadioMenuItem(MapRenderer.formatLength(mm));
      r.setToggleGroup(g);
      r.setSelected(w.view().options().gridSize() == mm);
      r.setOnAction(e -> setOptions(w.view().options().withGridSize(mm)));
      size.getItems().add(r);
    }
    CheckMenuItem points = check("Points", "menu-points", null, w.view().options().points());
    points.setOnAction(e -> setOptions(w.view().options().withPoints(points.isSelected())));
    CheckMenuItem lines = check("Lines", "menu-lines", null, w.view().options().lines());
    lines.setOnAction(e -> setOptions(w.view().options().withLines(lines.isSelected())));
    CheckMenuItem labels = check("Names", "menu-labels", null, w.view().options().labels());
    labels.setOnAction(e -> setOptions(w.view().options().withLabels(labels.isSelected())));
    return new Menu(
        "_View",
        null,
        item("Zoom In", "menu-zoom-in", "Shortcut+EQUALS", () -> w.view().zoom(1.5)),
        item("Zoom Out", "menu-zoom-out", "Shortcut+MINUS", () -> w.view().zoom(1 / 1.5)),
        item("Fit Map", "menu-fit", "Shortcut+DIGIT0", w.view()::fit),
        new SeparatorMenuItem(),
        grid,
        snap,
        size,
        new SeparatorMenuItem(),
        points,
        lines,
        labels);
  }

  private static CheckMenuItem check(String text, String id, String accel, boolean on) {
    CheckMenuItem c = new CheckMenuItem(text);
    c.setId(id);
    c.setSelected(on);
    if (accel != null) {
      c.setAccelerator(KeyCombination.keyCombination(accel));
    }
    return c;
  }

  private void setOptions(RenderOptions o) {
    w.view().setOptions(o);
    w.saveViewOptions();
  }

  private Menu toolsMenu() {
    Menu m = new Menu("_Tools");
    for (ToolEntry t : tools.values()) {
      MenuItem i = new MenuItem(t.tool().name() + "    " + keyText(t));
      i.setId("menu-tool-" + t.id());
      i.setOnAction(e -> select(t.id()));
      m.getItems().add(i);
    }
    return m;
  }

  private Menu helpMenu() {
    return new Menu(
        "_Help", null, item("Keyboard Shortcuts", "menu-keys", "F1", this::showShortcuts));
  }

  /** Help → Keyboard Shortcuts. */
  void showShortcuts() {
    List<String> intro = new ArrayList<>();
    intro.add("Tools (keys work while the map has the keyboard)");
    for (ToolEntry t : tools.values()) {
      intro.add(String.format(Locale.ROOT, "  %-18s %s", keyText(t), t.tool().name()));
    }
    intro.add("");
    intro.add("Mouse and keys on the map");
    intro.add("  Wheel              zoom about the pointer");
    intro.add("  Right/middle drag  pan (also Space + drag, or the arrow keys)");
    intro.add("  Shift              lines at 45° steps; headings and rotation in 15° steps");
    intro.add("  Double-click       rename an object (Select tool)");
    intro.add("  Del, Backspace     delete the selection");
    intro.add("  Esc                cancel a drag, select nothing");
    intro.add("  Ctrl+Shift+Z       redo");
    w.prompts().info("Keyboard shortcuts", ShortcutHelp.text(intro, menuBar));
  }

  // ------------------------------------------------------------------ actions

  private void openDialog() {
    if (!w.confirmDiscard()) {
      return;
    }
    w.prompts().chooseOpenFile("Open map", MapperWindow.MAP_FILTER, w.lastDir()).ifPresent(w::open);
  }

  private void quit() {
    if (w.confirmDiscard()) {
      // Already asked: close without asking again.
      w.window().setOnCloseRequest(null);
      w.window().close();
    }
  }

  void deleteSelection() {
    MapSelection s = w.selection();
    if (s.isEmpty()) {
      w.status("Nothing selected to delete");
      return;
    }
    w.document().execute(MapEdits.delete(s.ids(), s.points()));
    s.clear();
  }

  private void selectAll() {
    Set<Long> ids = new HashSet<>();
    MapContent c = w.document().content();
    c.lines().forEach(l -> ids.add(l.id()));
    c.objects().forEach(o -> ids.add(o.id()));
    BitSet p = new BitSet();
    p.set(0, c.points().size());
    w.selection().set(ids, p);
  }

  private void renameSelection() {
    long id = w.selection().single();
    if (id < 0) {
      w.status("Select one object to rename");
      return;
    }
    w.rename(id);
  }

  private void rotateSelection() {
    long id = w.selection().single();
    Optional<MapObjectEntry> e = id < 0 ? Optional.empty() : w.document().content().findObject(id);
    if (e.isEmpty()) {
      w.status("Select one object to rotate");
      return;
    }
    String now = Double.toString(e.get().object().pose().th());
    w.prompts()
        .askText("Rotate", "Heading in degrees (counter-clockwise from +x)", now)
        .ifPresent(
            s -> {
              try {
                double th = Double.parseDouble(s.trim().replace(',', '.'));
                w.document()
                    .execute(
                        MapEdits.replace(
                            "Rotate", id, MapGeometry.withHeading(e.get().object(), th)));
              } catch (NumberFormatException ex) {
                w.prompts().error("Not a heading", "'" + s + "' is not a number of degrees.");
              }
            });
  }

  private void exportDialog() {
    String name = w.document().title().replaceFirst("\\.map$", "") + ".png";
    w.prompts()
        .chooseSaveFile("Export PNG", List.of("PNG images|*.png"), w.lastDir(), name)
        .ifPresent(this::export);
  }

  /**
   * Renders the whole map (at most 4000 pixels a side) and writes it as PNG, on the worker thread:
   * the tiles are drawn on the JavaFX thread one at a time, so the window keeps answering, and the
   * status bar shows the progress.
   */
  void export(Path file) {
    MapContent content = w.document().content();
    RenderOptions options = w.view().options();
    BackgroundWork work = w.work();
    work.submit(
        "Exporting " + file.getFileName(),
        () -> {
          RgbImage img =
              MapExport.render(
                  content,
                  options,
                  4000,
                  f -> Platform.runLater(() -> work.progressProperty().set(f)));
          Path abs = file.toAbsolutePath();
          Path tmp = abs.resolveSibling("." + abs.getFileName() + ".saving");
          try {
            Files.write(tmp, ImageFiles.encode(img, "png"));
            Files.move(tmp, abs, StandardCopyOption.REPLACE_EXISTING);
          } finally {
            Files.deleteIfExists(tmp);
          }
          return file;
        },
        f -> w.status("Exported " + f),
        e ->
            w.prompts()
                .error(
                    "Cannot export",
                    "Writing "
                        + file
                        + " failed: "
                        + e.getMessage()
                        + "\n\nChoose a writable folder."));
  }
}
