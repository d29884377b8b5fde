package org.jaria.apps.mapper;

import javafx.scene.input.MouseEvent;

/** Adds a sensor point where you click (and more while dragging, one per grid step or 50 mm). */
public final class PointTool implements MapTool {

  private double[] last;

  @Override
  public String name() {
    return "Point";
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    last = add(c, e);
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    if (last == null) {
      return;
    }
    double[] p = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    double spacing = Math.max(50, c.snapStep());
    if (Math.hypot(p[0] - last[0], p[1] - last[1]) >= spacing) {
      last = add(c, e);
    }
  }

  private static double[] add(ToolContext c, MouseEvent e) {
    double[] p = c.snap(c.viewport().toWorldX(e.getX()), c.viewport().toWorldY(e.getY()));
    c.document()
        .execute(
            MapEdits.addPoints(
                new int[] {(int) Math.round(p[0])}, new int[] {(int) Math.round(p[1])}));
    c.redraw();
    return p;
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    last = null;
  }

  @Override
  public void cancel() {
    last = null;
  }
}
