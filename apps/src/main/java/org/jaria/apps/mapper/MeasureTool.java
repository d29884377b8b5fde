package org.jaria.apps.mapper;

import java.util.Locale;
import javafx.geometry.VPos;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;
import javafx.scene.paint.Color;
import javafx.scene.text.Font;
import javafx.scene.text.TextAlignment;
import org.jaria.apps.fx.Viewport;

/** Measures a distance and direction by dragging; the result stays shown until the next drag. */
public final class MeasureTool implements MapTool {

  private static final Color INK = Color.web("#8a2be2");
  private double[] start;
  private double[] end;

  @Override
  public String name() {
    return "Measure";
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    start = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    end = start;
    c.redraw();
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    if (start == null) {
      return;
    }
    end = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    c.status(text());
    c.redraw();
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    if (start != null) {
      c.status(text());
    }
  }

  /** The last measurement, e.g. "3.25 m at 90°", or "" if none. */
  public String text() {
    if (start == null) {
      return "";
    }
    double dx = end[0] - start[0];
    double dy = end[1] - start[1];
    return String.format(
        Locale.ROOT,
        "%s at %.0f° (dx %s, dy %s)",
        MapRenderer.formatLength(Math.hypot(dx, dy)),
        Math.toDegrees(Math.atan2(dy, dx)),
        MapRenderer.formatLength(dx),
        MapRenderer.formatLength(dy));
  }

  /** The measured length in mm (0 if nothing measured). */
  public double length() {
    return start == null ? 0 : Math.hypot(end[0] - start[0], end[1] - start[1]);
  }

  @Override
  public void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer r) {
    if (start == null) {
      return;
    }
    Viewport vp = c.viewport();
    double x1 = vp.toScreenX(start[0]);
    double y1 = vp.toScreenY(start[1]);
    double x2 = vp.toScreenX(end[0]);
    double y2 = vp.toScreenY(end[1]);
    gc.setStroke(INK);
    gc.setLineWidth(2);
    gc.setLineDashes(6, 4);
    gc.strokeLine(x1, y1, x2, y2);
    gc.setLineDashes();
    gc.strokeOval(x1 - 3, y1 - 3, 6, 6);
    gc.strokeOval(x2 - 3, y2 - 3, 6, 6);
    gc.setFont(Font.font("System", 12));
    gc.setTextAlign(TextAlignment.LEFT);
    gc.setTextBaseline(VPos.BOTTOM);
    gc.setFill(INK);
    gc.fillText(MapRenderer.formatLength(length()), x2 + 8, y2 - 6);
  }

  @Override
  public void cancel() {
    start = null;
  }
}
