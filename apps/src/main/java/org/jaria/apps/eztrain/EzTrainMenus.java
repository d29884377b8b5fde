package org.jaria.apps.eztrain;

import java.util.Locale;
import javafx.beans.property.ObjectProperty;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;
import javafx.scene.control.RadioMenuItem;
import javafx.scene.control.SeparatorMenuItem;
import javafx.scene.control.ToggleGroup;
import javafx.scene.input.KeyCombination;

/** EZ-Train's menus: File, Edit, Settings (view mode, brush, colours, magnification) and Info. */
final class EzTrainMenus {

  private final MenuBar bar;

  EzTrainMenus(EzTrainWindow w, EzTrainState state) {
    bar =
        new MenuBar(
            new Menu(
                "_File",
                null,
                item("Load Image…", "menu-load-image", "Shortcut+O", w.files()::loadImageDialog),
                item("Live Video (Camera)…", "menu-live-video", null, w.files()::liveVideoDialog),
                item("Simulator Camera", "menu-sim-camera", null, w.files()::simulatorCamera),
                new SeparatorMenuItem(),
                item(
                    "Load Channel…",
                    "menu-load-channel",
                    "Shortcut+L",
                    w.files()::loadChannelDialog),
                item("Save Channel", "menu-save-channel", "Shortcut+S", w.files()::saveChannel),
                item(
                    "Save Channel As…",
                    "menu-save-channel-as",
                    "Shortcut+Shift+S",
                    w.files()::saveChannelAsDialog),
                new SeparatorMenuItem(),
                item("Load Runtime Config…", "menu-load-config", null, w.files()::loadConfigDialog),
                item("Save Runtime Config…", "menu-save-config", null, w.files()::saveConfigDialog),
                new SeparatorMenuItem(),
                item("Quit  (Esc)", "menu-quit", "Shortcut+Q", w::quit)),
            new Menu(
                "_Edit",
                null,
                item("Undo", "menu-undo", "Shortcut+Z", w::undo),
                item("Clear Training…", "menu-clear", null, w::clearTraining)),
            settings(state),
            new Menu(
                "_Info",
                null,
                item("Blob Stats", "menu-blob-stats", "Shortcut+B", w::blobStats),
                item("Timing", "menu-timing", "Shortcut+T", w::timing)));
    addHelp(w);
  }

  private void addHelp(EzTrainWindow w) {
    bar.getMenus()
        .add(
            new Menu(
                "_Help",
                null,
                item("Keyboard Shortcuts", "menu-keys", "F1", () -> w.showShortcuts(bar))));
  }

  MenuBar menuBar() {
    return bar;
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

  private static Menu settings(EzTrainState state) {
    Menu view = new Menu("View Mode");
    view.setId("menu-view");
    ToggleGroup vg = new ToggleGroup();
    for (ViewMode m : ViewMode.values()) {
      RadioMenuItem r = new RadioMenuItem(m.label() + "    " + m.key());
      r.setId("menu-view-" + m.name().toLowerCase(Locale.ROOT));
      r.setToggleGroup(vg);
      r.setSelected(state.viewMode.get() == m);
      r.setOnAction(e -> state.viewMode.set(m));
      state.viewMode.addListener((o, was, now) -> r.setSelected(now == m));
      view.getItems().add(r);
    }
    Menu brush = new Menu("Brush Size");
    brush.setId("menu-brush");
    ToggleGroup bg = new ToggleGroup();
    for (int s = 1; s <= 9; s += 2) {
      int size = s;
      RadioMenuItem r = new RadioMenuItem(s + " × " + s);
      r.setId("menu-brush-" + s);
      r.setToggleGroup(bg);
      r.setSelected(state.brush.get() == s);
      r.setOnAction(e -> state.brush.set(size));
      brush.getItems().add(r);
    }
    Menu mag = new Menu("Magnification");
    mag.setId("menu-magnification");
    ToggleGroup mg = new ToggleGroup();
    for (int m = 1; m <= 6; m++) {
      int f = m;
      RadioMenuItem r = new RadioMenuItem(m + "×");
      r.setId("menu-magnification-" + m);
      r.setToggleGroup(mg);
      r.setSelected(state.magnification.get() == m);
      r.setOnAction(e -> state.magnification.set(f));
      state.magnification.addListener((o, was, now) -> r.setSelected(now.intValue() == f));
      mag.getItems().add(r);
    }
    return new Menu(
        "_Settings",
        null,
        view,
        brush,
        colors("Draw Color", "menu-draw", state.drawColor),
        colors("Thresh Color", "menu-thresh", state.threshColor),
        mag);
  }

  private static Menu colors(String title, String id, ObjectProperty<MarkColor> prop) {
    Menu m = new Menu(title);
    m.setId(id);
    ToggleGroup g = new ToggleGroup();
    for (MarkColor c : MarkColor.values()) {
      RadioMenuItem r = new RadioMenuItem(c.label());
      r.setId(id + "-" + c.name().toLowerCase(Locale.ROOT));
      r.setToggleGroup(g);
      r.setSelected(prop.get() == c);
      r.setOnAction(e -> prop.set(c));
      prop.addListener((o, was, now) -> r.setSelected(now == c));
      m.getItems().add(r);
    }
    return m;
  }
}
