package org.jaria.apps.mapper;

import java.util.BitSet;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import javafx.scene.Cursor;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseEvent;
import javafx.scene.paint.Color;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArMath;
import org.jaria.map.ArMapObject;

/**
 * Selects, moves and rotates. Click an item to select it (Shift adds or removes), drag a box over
 * empty space to select everything inside it, drag a selected item to move the selection, drag the
 * round handle of a selected area to rotate it (Shift: steps of 15°), double-click an object to
 * rename it.
 */
public final class SelectTool implements MapTool {

  private enum Mode {
    NONE,
    MOVE,
    BOX,
    ROTATE
  }

  private Mode mode = Mode.NONE;
  private double startX;
  private double startY;
  private double curX;
  private double curY;
  private boolean additive;
  private double rotation;

  @Override
  public String name() {
    return "Select";
  }

  @Override
  public Cursor cursor() {
    return Cursor.DEFAULT;
  }

  @Override
  public void pressed(ToolContext c, MouseEvent e) {
    Viewport vp = c.viewport();
    startX = vp.toWorldX(e.getX());
    startY = vp.toWorldY(e.getY());
    curX = startX;
    curY = startY;
    additive = e.isShiftDown() || e.isShortcutDown();
    MapObjectEntry area = selectedArea(c);
    if (area != null) {
      double[] h = MapRenderer.rotationHandle(vp, area.object());
      if (Math.hypot(h[0] - e.getX(), h[1] - e.getY()) <= 9) {
        mode = Mode.ROTATE;
        rotation = area.object().pose().th();
        return;
      }
    }
    ToolContext.Hit hit = c.hit(e.getX(), e.getY());
    if (hit.any()) {
      boolean selected =
          hit.id() >= 0
              ? c.selection().contains(hit.id())
              : c.selection().containsPoint(hit.point());
      BitSet p = new BitSet();
      if (hit.point() >= 0) {
        p.set(hit.point());
      }
      Set<Long> ids = hit.id() >= 0 ? Set.of(hit.id()) : Set.of();
      if (additive) {
        if (hit.id() >= 0) {
          c.selection().toggle(hit.id());
        } else {
          c.selection().add(ids, p);
        }
        mode = Mode.NONE;
        return;
      }
      if (!selected) {
        c.selection().set(ids, p);
      }
      mode = Mode.MOVE;
    } else {
      if (!additive) {
        c.selection().clear();
      }
      mode = Mode.BOX;
    }
    c.redraw();
  }

  @Override
  public void dragged(ToolContext c, MouseEvent e) {
    curX = c.viewport().toWorldX(e.getX());
    curY = c.viewport().toWorldY(e.getY());
    if (mode == Mode.ROTATE) {
      MapObjectEntry area = selectedArea(c);
      if (area != null) {
        double[] mid = MapGeometry.center(area.object());
        double a = Math.toDegrees(Math.atan2(curY - mid[1], curX - mid[0])) - 90;
        double step = e.isShiftDown() ? 15 : 1;
        rotation = ArMath.fixAngle(Math.round(a / step) * step);
        c.status(String.format(Locale.ROOT, "Heading %.0f°", rotation));
      }
    } else if (mode == Mode.MOVE) {
      double[] d = delta(c);
      c.status("Move by " + MapRenderer.formatLength(d[0]) + ", " + MapRenderer.formatLength(d[1]));
    }
    c.redraw();
  }

  private double[] delta(ToolContext c) {
    double dx = curX - startX;
    double dy = curY - startY;
    double step = c.snapStep();
    if (step > 0) {
      dx = Math.round(dx / step) * step;
      dy = Math.round(dy / step) * step;
    }
    return new double[] {dx, dy};
  }

  @Override
  public void released(ToolContext c, MouseEvent e) {
    Mode m = mode;
    mode = Mode.NONE;
    switch (m) {
      case MOVE -> {
        double[] d = delta(c);
        long single = c.selection().single();
        if (d[0] == 0 && d[1] == 0 && e.getClickCount() == 2 && single >= 0) {
          // A double click that did not move anything: rename.
          c.rename(single);
        } else if ((d[0] != 0 || d[1] != 0) && !c.selection().isEmpty()) {
          c.document()
              .execute(MapEdits.move(c.selection().ids(), c.selection().points(), d[0], d[1]));
        }
      }
      case BOX -> selectBox(c);
      case ROTATE -> {
        MapObjectEntry area = selectedArea(c);
        if (area != null && rotation != area.object().pose().th()) {
          c.document()
              .execute(
                  MapEdits.replace(
                      "Rotate", area.id(), MapGeometry.withHeading(area.object(), rotation)));
        }
      }
      case NONE -> {}
    }
    c.redraw();
  }

  private void selectBox(ToolContext c) {
    Set<Long> ids = new HashSet<>();
    for (MapLine l : c.document().content().lines()) {
      if (MapGeometry.inside(l.segment(), startX, startY, curX, curY)) {
        ids.add(l.id());
      }
    }
    for (MapObjectEntry o : c.document().content().objects()) {
      if (MapGeometry.inside(o.object(), startX, startY, curX, curY)) {
        ids.add(o.id());
      }
    }
    BitSet p = new BitSet();
    if (c.points() != null) {
      c.points().select(startX, startY, curX, curY, p);
    }
    if (additive) {
      c.selection().add(ids, p);
    } else {
      c.selection().set(ids, p);
    }
    c.status(c.selection().size() + " selected");
  }

  private static MapObjectEntry selectedArea(ToolContext c) {
    long id = c.selection().single();
    if (id < 0) {
      return null;
    }
    return c.document().content().findObject(id).filter(o -> o.object().isAreaType()).orElse(null);
  }

  @Override
  public void drawOverlay(ToolContext c, GraphicsContext gc, MapRenderer r) {
    Viewport vp = c.viewport();
    switch (mode) {
      case BOX -> {
        double x = Math.min(vp.toScreenX(startX), vp.toScreenX(curX));
        double y = Math.min(vp.toScreenY(startY), vp.toScreenY(curY));
        double w = Math.abs(vp.toScreenX(curX) - vp.toScreenX(startX));
        double h = Math.abs(vp.toScreenY(curY) - vp.toScreenY(startY));
        gc.setFill(Color.web("#1e78ff", 0.1));
        gc.fillRect(x, y, w, h);
        gc.setStroke(MapRenderer.SELECTION);
        gc.setLineWidth(1);
        gc.setLineDashes(4, 3);
        gc.strokeRect(x + 0.5, y + 0.5, w, h);
        gc.setLineDashes();
      }
      case MOVE -> {
        double[] d = delta(c);
        Set<Long> ids = c.selection().ids();
        for (MapLine l : c.document().content().lines()) {
          if (ids.contains(l.id())) {
            ArLineSegment s = l.segment();
            r.drawPreviewLine(
                gc,
                vp,
                new ArLineSegment(s.x1() + d[0], s.y1() + d[1], s.x2() + d[0], s.y2() + d[1]),
                MapRenderer.SELECTION);
          }
        }
        for (MapObjectEntry o : c.document().content().objects()) {
          if (ids.contains(o.id())) {
            r.drawObject(gc, vp, o.object(), true, false, d[0], d[1]);
          }
        }
      }
      case ROTATE -> {
        MapObjectEntry area = selectedArea(c);
        if (area != null) {
          ArMapObject turned = MapGeometry.withHeading(area.object(), rotation);
          r.drawObject(gc, vp, turned, true, false, 0, 0);
        }
      }
      case NONE -> {}
    }
  }

  @Override
  public void cancel() {
    mode = Mode.NONE;
  }
}
