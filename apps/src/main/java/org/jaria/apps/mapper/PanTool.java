package org.jaria.apps.mapper;

import javafx.scene.Cursor;
import javafx.scene.input.MouseEvent;

/**
 * Moves the view with the primary button (the middle and right buttons, and Space with the primary
 * button, do the same with any tool).
 */
public final class PanTool implements MapTool {

  private double lastX;
  private double lastY;

  @Override
  public String name() {
    return "Pan";
  }

  @Override
  public Cursor cursor() {
    return Cursor.OPEN_HAND;
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    lastX = e.getX();
    lastY = e.getY();
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    c.viewport().panPixels(e.getX() - lastX, e.getY() - lastY);
    lastX = e.getX();
    lastY = e.getY();
    c.redraw();
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {}
}
