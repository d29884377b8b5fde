package org.jaria.apps.fx;

import javafx.geometry.Rectangle2D;
import javafx.stage.Screen;
import javafx.stage.Stage;
import javafx.stage.WindowEvent;

/**
 * Remembers where a window was and how big: restores position, size and the maximized state when
 * the window opens (if that place is still on a screen) and stores them when it closes.
 */
public final class WindowState {

  private WindowState() {}

  /**
   * Sizes {@code stage} from the stored state (or {@code defaultWidth} × {@code defaultHeight} the
   * first time) and stores its state again whenever it is hidden. Call before showing the stage.
   */
  public static void remember(
      Stage stage, AppPrefs prefs, String key, double defaultWidth, double defaultHeight) {
    double w = prefs.getDouble(key + ".width", defaultWidth);
    double h = prefs.getDouble(key + ".height", defaultHeight);
    double x = prefs.getDouble(key + ".x", Double.NaN);
    double y = prefs.getDouble(key + ".y", Double.NaN);
    stage.setWidth(Math.max(320, w));
    stage.setHeight(Math.max(240, h));
    if (!Double.isNaN(x) && !Double.isNaN(y) && isVisibleOnSomeScreen(x, y, w, h)) {
      stage.setX(x);
      stage.setY(y);
    } else {
      stage.centerOnScreen();
    }
    stage.setMaximized(prefs.getBoolean(key + ".maximized", false));
    stage.addEventHandler(WindowEvent.WINDOW_HIDING, e -> store(stage, prefs, key));
  }

  /** Stores the stage's current position, size and maximized state. */
  public static void store(Stage stage, AppPrefs prefs, String key) {
    prefs.putBoolean(key + ".maximized", stage.isMaximized());
    if (!stage.isMaximized()) {
      prefs.putDouble(key + ".x", stage.getX());
      prefs.putDouble(key + ".y", stage.getY());
      prefs.putDouble(key + ".width", stage.getWidth());
      prefs.putDouble(key + ".height", stage.getHeight());
    }
    prefs.flush();
  }

  // A window whose title bar is on no screen (a monitor was unplugged) could not be moved back.
  private static boolean isVisibleOnSomeScreen(double x, double y, double w, double h) {
    for (Screen s : Screen.getScreens()) {
      Rectangle2D b = s.getVisualBounds();
      if (b.intersects(x + 20, y, Math.max(1, w - 40), Math.min(30, h))) {
        return true;
      }
    }
    return false;
  }
}
