package org.jaria.apps.mapper;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;
import org.jaria.apps.fx.Viewport;
import org.jaria.map.ArMapObject;

/**
 * Draws a forbidden area by dragging a rectangle from corner to corner. The area is stored as
 * Mapper3 stores it (pose 0 0 0 and absolute corners); select it and drag its round handle to
 * rotate it.
 */
public final class AreaTool implements MapTool {

  private double[] start;
  private double[] end;

  @Override
  public String name() {
    return "Forbidden area";
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    start = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    end = start;
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    if (start == null) {
      return;
    }
    end = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    c.status(
        "Forbidden area "
            + MapRenderer.formatLength(Math.abs(end[0] - start[0]))
            + " × "
            + MapRenderer.formatLength(Math.abs(end[1] - start[1])));
    c.redraw();
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    if (start == null) {
      return;
    }
    double[] a = start;
    double[] b = end;
    start = null;
    if (Math.abs(b[0] - a[0]) >= 1 && Math.abs(b[1] - a[1]) >= 1) {
      c.document().execute(MapEdits.addObject(ArMapObject.forbiddenArea(a[0], a[1], b[0], b[1])));
    }
    c.redraw();
  }

  @Override
  public void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer r) {
    if (start != null) {
      Viewport vp = c.viewport();
      r.drawObject(
          gc,
          vp,
          ArMapObject.forbiddenArea(start[0], start[1], end[0], end[1]),
          false,
          false,
          0,
          0);
    }
  }

  @Override
  public void cancel() {
    start = null;
  }
}
