package org.jaria.apps.mapper;

import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Viewport;

/** What a {@link MapTool} can see and do: the map, the selection, the view, snapping, picking. */
public interface ToolContext {

  /** The map being edited. */
  MapDocument document();

  /** The selection. */
  MapSelection selection();

  /** The view's coordinate mapping. */
  Viewport viewport();

  /** The sensor points' index (for picking and box selection). */
  PointLayer points();

  /** (x, y) in mm moved to the nearest grid point if snapping is on, as {x, y}. */
  double[] snap(double x, double y);

  /** The snapping step in mm, or 0 when snapping is off. */
  double snapStep();

  /**
   * What is under view point (sx, sy).
   *
   * @return the hit (an item, a point, or nothing)
   */
  Hit hit(double sx, double sy);

  /** Asks for the view to be drawn again. */
  void redraw();

  /** Shows a short message in the status bar. */
  void status(String text);

  /** Opens the rename dialog for object {@code id}. */
  void rename(long id);

  /**
   * What is under the mouse.
   *
   * @param id editor number of a line or object, or -1
   * @param point index of a sensor point, or -1
   */
  record Hit(long id, int point) {
    /** Nothing. */
    public static final Hit NONE = new Hit(-1, -1);

    /** Whether something was hit. */
    public boolean any() {
      return id >= 0 || point >= 0;
    }
  }
}
