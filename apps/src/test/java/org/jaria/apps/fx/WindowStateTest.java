package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javafx.scene.Scene;
import javafx.scene.layout.Pane;
import javafx.stage.Stage;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.framework.junit5.ApplicationExtension;

/** Window size and place survive closing and reopening (in a test store, not the user's). */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class WindowStateTest {

  @Test
  void sizeAndPlaceAreRememberedInTheGivenStore() {
    AppPrefs prefs = AppPrefs.inMemory();
    FxRuntime.run(
        () -> {
          Stage s = new Stage();
          s.setScene(new Scene(new Pane()));
          WindowState.remember(s, prefs, "w", 640, 480);
          s.show();
          assertEquals(640, s.getWidth(), 1);
          s.setX(30);
          s.setY(40);
          s.setWidth(700);
          s.setHeight(500);
          s.hide();
        },
        10);
    assertEquals("700.0", prefs.get("w.width", ""));
    FxRuntime.run(
        () -> {
          Stage s = new Stage();
          s.setScene(new Scene(new Pane()));
          WindowState.remember(s, prefs, "w", 640, 480);
          s.show();
          assertEquals(700, s.getWidth(), 1);
          assertEquals(500, s.getHeight(), 1);
          assertEquals(30, s.getX(), 1);
          assertEquals(40, s.getY(), 1);
          s.hide();
        },
        10);
  }

  @Test
  void offScreenPlaceIsNotRestoredAndBadNumbersFallBack() {
    AppPrefs prefs = AppPrefs.inMemory();
    prefs.putDouble("w.x", 50_000);
    prefs.putDouble("w.y", 50_000);
    prefs.put("w.width", "wide");
    FxRuntime.run(
        () -> {
          Stage s = new Stage();
          s.setScene(new Scene(new Pane()));
          WindowState.remember(s, prefs, "w", 640, 480);
          s.show();
          assertEquals(640, s.getWidth(), 1);
          assertTrue(s.getX() < 10_000, "centred on a screen instead");
          s.hide();
        },
        10);
  }
}
