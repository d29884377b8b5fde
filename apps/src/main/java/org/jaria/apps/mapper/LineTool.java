package org.jaria.apps.mapper;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;

/**
 * Draws a wall line, or a forbidden line, by dragging from one end to the other (snapped to the
 * grid when snapping is on; Shift keeps the line horizontal, vertical or diagonal).
 */
public final class LineTool implements MapTool {

  private final boolean forbidden;
  private double[] start;
  private double[] end;

  /** A tool for walls ({@code forbidden} false) or forbidden lines (true). */
  public LineTool(boolean forbidden) {
    this.forbidden = forbidden;
  }

  @Override
  public String name() {
    return forbidden ? "Forbidden line" : "Wall";
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
    if (e.isShiftDown()) {
      end = constrain(start, end);
    }
    c.status(
        name() + ": " + MapRenderer.formatLength(Math.hypot(end[0] - start[0], end[1] - start[1])));
    c.redraw();
  }

  /** {@code end} moved onto the nearest multiple of 45° from {@code start}. */
  static double[] constrain(double[] start, double[] end) {
    double dx = end[0] - start[0];
    double dy = end[1] - start[1];
    double len = Math.hypot(dx, dy);
    double a = Math.round(Math.atan2(dy, dx) / (Math.PI / 4)) * (Math.PI / 4);
    return new double[] {start[0] + len * Math.cos(a), start[1] + len * Math.sin(a)};
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    if (start == null) {
      return;
    }
    double[] a = start;
    double[] b = end;
    start = null;
    if (Math.hypot(b[0] - a[0], b[1] - a[1]) < 1) {
      c.redraw();
      return;
    }
    if (forbidden) {
      c.document().execute(MapEdits.addObject(ArMapObject.forbiddenLine(a[0], a[1], b[0], b[1])));
    } else {
      c.document().execute(MapEdits.addLine(new ArLineSegment(a[0], a[1], b[0], b[1])));
    }
    c.redraw();
  }

  @Override
  public void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer r) {
    if (start != null) {
      r.drawPreviewLine(
          gc,
          c.viewport(),
          new ArLineSegment(start[0], start[1], end[0], end[1]),
          forbidden ? MapRenderer.FORBIDDEN : MapRenderer.SELECTION);
    }
  }

  @Override
  public void cancel() {
    start = null;
  }
}
