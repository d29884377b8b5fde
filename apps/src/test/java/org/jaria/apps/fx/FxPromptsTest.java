package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The info dialog (F1's shortcut list) is as wide as its longest line, so nothing is cut off. */
class FxPromptsTest {

  @Test
  void theTextBoxIsWideEnoughForTheLongestLine() {
    String wide = "  Ctrl+Shift+E      Export as PNG with the grid, the labels and the legend…";
    assertEquals(wide.length() + 4, FxPrompts.columnsFor("Keys\n" + wide + "\nshort"));
    assertEquals(40, FxPrompts.columnsFor("short"), "never narrower than a readable box");
    assertEquals(120, FxPrompts.columnsFor("x".repeat(500)), "never wider than a screen");
  }
}
