package org.jaria.apps.mapper;

import javafx.scene.Cursor;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;

/**
 * A mouse tool of the map editor (select, draw a wall, place a goal, measure...). The view passes
 * it the primary-button events in view coordinates; panning with the middle or right button and
 * zooming with the wheel work whatever the tool.
 */
public interface MapTool {

  /** The tool's name for menus and the status bar. */
  String name();

  /** The mouse cursor over the map while this tool is active. */
  default Cursor cursor() {
    return Cursor.CROSSHAIR;
  }

  /** The primary button went down at (e.getX(), e.getY()). */
  void pressed(ToolContext c, MouseEvent e);

  /** The mouse moved with the primary button down. */
  void dragged(ToolContext c, MouseEvent e);

  /** The primary button came up. */
  void released(ToolContext c, MouseEvent e);

  /** The mouse moved with no button down. */
  default void moved(ToolContext c, MouseEvent e) {}

  /** Draws the tool's feedback (rubber band, preview, measurement) over the map. */
  default void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer renderer) {}

  /** Abandons a drag in progress (Escape, or another tool chosen). */
  default void cancel() {}
}
