package org.jaria.apps.fx;

import java.util.List;
import javafx.scene.control.Menu;
import javafx.scene.control.MenuBar;
import javafx.scene.control.MenuItem;
import javafx.scene.control.SeparatorMenuItem;
import javafx.scene.input.KeyCombination;

/**
 * The text of an app's Help → Keyboard Shortcuts: the keys the app describes itself (tools, mouse
 * gestures), then every menu command that has a shortcut, read from the menus so the list never
 * goes out of date.
 */
public final class ShortcutHelp {

  private ShortcutHelp() {}

  /**
   * The list.
   *
   * @param intro lines about keys and gestures outside the menus, e.g. "W draw a wall"
   * @param menus the app's menu bar
   */
  public static String text(List<String> intro, MenuBar menus) {
    StringBuilder b = new StringBuilder();
    for (String line : intro) {
      b.append(line).append('\n');
    }
    for (Menu m : menus.getMenus()) {
      StringBuilder part = new StringBuilder();
      collect(m, part);
      if (part.length() > 0) {
        b.append('\n').append(m.getText().replace("_", "")).append('\n').append(part);
      }
    }
    return b.toString().stripTrailing();
  }

  private static void collect(Menu menu, StringBuilder out) {
    for (MenuItem i : menu.getItems()) {
      if (i instanceof Menu sub) {
        collect(sub, out);
      } else if (!(i instanceof SeparatorMenuItem) && i.getAccelerator() != null) {
        KeyCombination k = i.getAccelerator();
        out.append(String.format("  %-18s %s%n", k.getDisplayText(), i.getText()));
      }
    }
  }
}
