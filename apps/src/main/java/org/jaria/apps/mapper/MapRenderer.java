package org.jaria.apps.mapper;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.ToDoubleFunction;
import javafx.geometry.VPos;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import javafx.scene.text.Font;
import javafx.scene.text.TextAlignment;
import org.jaria.apps.fx.LabelPlacer;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.TextWidths;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;

/**
 * Draws a map on a canvas: grid, sensor points, wall lines, objects with their symbols and names,
 * the selection, and a scale bar. Only what is in view is drawn (culling); the points go through
 * {@link PointLayer}. Stateless apart from reused buffers; JavaFX thread.
 */
public final class MapRenderer {

  /** Colour of selected items. */
  public static final Color SELECTION = Color.web("#1e78ff");

  static final Color WALL = Color.web("#202020");
  static final Color FORBIDDEN = Color.web("#d62020");
  static final Color FORBIDDEN_FILL = Color.web("#d62020", 0.18);
  static final Color GOAL = Color.web("#1a9e3a");
  static final Color HOME = Color.web("#1f5fd0");
  static final Color DOCK = Color.web("#b06000");
  static final Color OTHER = Color.web("#707070");
  static final Color OTHER_FILL = Color.web("#707070", 0.15);
  static final Color GRID = Color.web("#e6e9ef");
  static final Color GRID_AXIS = Color.web("#c9ced8");

  private static final int POINT_ARGB = 0xFF303030;
  private static final Color LABEL_BACKING = Color.rgb(255, 255, 255, 0.8);
  private static final int SELECTED_ARGB = 0xFF1E78FF;

  private final Font font = Font.font("System", 11);

  /** A label's height in pixels (the font's size and a little room). */
  private static final double LABEL_HEIGHT = 14;

  private final TextWidths widths = new TextWidths(font);

  private boolean scaleBar = true;

  /** Whether to draw the scale bar in the bottom-left corner (on by default). */
  public void setScaleBar(boolean on) {
    scaleBar = on;
  }

  /** Points drawn faintly under the map (a scan log's readings), or null. */
  void setUnderlay(PointLayer raw) {
    underlay = raw;
  }

  /** The underlay's colour: a light orange, so the map's black points stand out on it. */
  static final int UNDERLAY_ARGB = 0xFFF5C89A;

  private PointLayer underlay;

  /**
   * Draws everything.
   *
   * @param points the index of {@code content.points()} (may be null while it is built)
   */
  public void render(
      GraphicsContext gc,
      Viewport vp,
      MapContent content,
      PointLayer points,
      MapSelection selection,
      RenderOptions opt) {
    gc.setFill(Color.WHITE);
    gc.fillRect(0, 0, vp.width(), vp.height());
    if (opt.grid()) {
      drawGrid(gc, vp, opt.gridSize());
    }
    if (underlay != null) {
      gc.drawImage(underlay.render(vp, UNDERLAY_ARGB, null, 0, opt.pointSize()), 0, 0);
    }
    if (opt.points() && points != null) {
      BitSet sel = selection == null ? null : selection.points();
      gc.drawImage(points.render(vp, POINT_ARGB, sel, SELECTED_ARGB, opt.pointSize()), 0, 0);
    }
    if (opt.lines()) {
      drawLines(gc, vp, content.lines(), selection);
    }
    // Markers first, then the names where they do not overlap (selected objects' names first,
    // so those always show).
    Set<String> selectedNames = new HashSet<>();
    for (MapObjectEntry e : content.objects()) {
      boolean selected = selection != null && selection.contains(e.id());
      drawObject(gc, vp, e.object(), selected, false, 0, 0);
      if (selected) {
        selectedNames.add(e.object().name());
      }
    }
    gc.setFont(font);
    gc.setTextAlign(TextAlignment.LEFT);
    gc.setTextBaseline(VPos.CENTER);
    List<LabelPlacer.Placed> labels =
        opt.labels()
            ? placeLabels(
                content.objects(),
                opt.lines() ? content.lines() : List.of(),
                selection,
                vp,
                widths::of,
                LABEL_HEIGHT)
            : List.of();
    for (LabelPlacer.Placed p : labels) {
      String name = p.label().text();
      // A pale backing: names stay legible over dense laser points and walls.
      gc.setFill(LABEL_BACKING);
      gc.fillRect(p.left() - 1, p.top(), p.label().width() + 1, p.label().height());
      gc.setFill(Color.WHITE);
      gc.fillText(name, p.left() + 0.8, p.centerY() + 0.8);
      gc.setFill(selectedNames.contains(name) ? SELECTION : Color.web("#202020"));
      gc.fillText(name, p.left(), p.centerY());
    }
    if (scaleBar) {
      drawScaleBar(gc, vp);
    }
  }

  /**
   * Where the names of the objects go on the picture {@code vp} shows: the selected objects' first,
   * none over a marker (named or not) or another name, none past the picture's edge, across a wall
   * only where no side is clear of them.
   */
  static List<LabelPlacer.Placed> placeLabels(
      List<MapObjectEntry> objects,
      List<MapLine> walls,
      MapSelection selection,
      Viewport vp,
      ToDoubleFunction<String> textWidth,
      double labelHeight) {
    List<LabelPlacer.Label> selectedLabels = new ArrayList<>();
    List<LabelPlacer.Label> otherLabels = new ArrayList<>();
    double[] unnamed = new double[2 * objects.size()];
    int n = 0;
    for (MapObjectEntry e : objects) {
      ArMapObject o = e.object();
      if (o.hasFromTo()) {
        continue;
      }
      double x = vp.toScreenX(o.pose().x());
      double y = vp.toScreenY(o.pose().y());
      if (x < -60 || y < -60 || x > vp.width() + 60 || y > vp.height() + 60) {
        continue;
      }
      if (o.name().isEmpty()) {
        unnamed[n++] = x;
        unnamed[n++] = y;
      } else {
        boolean selected = selection != null && selection.contains(e.id());
        (selected ? selectedLabels : otherLabels)
            .add(
                new LabelPlacer.Label(
                    x, y, textWidth.applyAsDouble(o.name()), labelHeight, o.name()));
      }
    }
    selectedLabels.addAll(otherLabels);
    double[] lines = new double[4 * walls.size()];
    int k = 0;
    for (MapLine l : walls) {
      ArLineSegment s = l.segment();
      if (vp.intersects(s.x1(), s.y1(), s.x2(), s.y2())) {
        lines[k++] = vp.toScreenX(s.x1());
        lines[k++] = vp.toScreenY(s.y1());
        lines[k++] = vp.toScreenX(s.x2());
        lines[k++] = vp.toScreenY(s.y2());
      }
    }
    return LabelPlacer.place(
        selectedLabels,
        Arrays.copyOf(unnamed, n),
        Arrays.copyOf(lines, k),
        vp.width(),
        vp.height());
  }

  // Grid lines are 1-pixel filled rectangles, not stroked lines: axis-aligned fills are an order
  // of magnitude cheaper than anti-aliased strokes in the software renderer (headless, remote X).
  private static void drawGrid(GraphicsContext gc, Viewport vp, double size) {
    double step = size;
    while (step * vp.scale() < 12) {
      step *= step * vp.scale() < 1.6 ? 10 : 5;
    }
    double x0 = Math.floor(vp.minVisibleX() / step) * step;
    for (double x = x0; x <= vp.maxVisibleX(); x += step) {
      gc.setFill(Math.abs(x) < step / 2 ? GRID_AXIS : GRID);
      gc.fillRect(Math.floor(vp.toScreenX(x)), 0, 1, vp.height());
    }
    double y0 = Math.floor(vp.minVisibleY() / step) * step;
    for (double y = y0; y <= vp.maxVisibleY(); y += step) {
      gc.setFill(Math.abs(y) < step / 2 ? GRID_AXIS : GRID);
      gc.fillRect(0, Math.floor(vp.toScreenY(y)), vp.width(), 1);
    }
  }

  private static void drawLines(
      GraphicsContext gc, Viewport vp, List<MapLine> lines, MapSelection selection) {
    gc.setLineWidth(vp.scale() > 0.2 ? 2 : 1);
    gc.setStroke(WALL);
    for (MapLine l : lines) {
      ArLineSegment s = l.segment();
      if (!vp.intersects(s.x1(), s.y1(), s.x2(), s.y2())) {
        continue;
      }
      boolean sel = selection != null && selection.contains(l.id());
      if (sel) {
        gc.setStroke(SELECTION);
        gc.setLineWidth(3);
      }
      gc.strokeLine(
          vp.toScreenX(s.x1()), vp.toScreenY(s.y1()), vp.toScreenX(s.x2()), vp.toScreenY(s.y2()));
      if (sel) {
        gc.setStroke(WALL);
        gc.setLineWidth(vp.scale() > 0.2 ? 2 : 1);
        handle(gc, vp.toScreenX(s.x1()), vp.toScreenY(s.y1()));
        handle(gc, vp.toScreenX(s.x2()), vp.toScreenY(s.y2()));
      }
    }
  }

  /** Draws a line as a preview (tools, moves). */
  public void drawPreviewLine(GraphicsContext gc, Viewport vp, ArLineSegment s, Color c) {
    gc.setStroke(c);
    gc.setLineWidth(2);
    gc.strokeLine(
        vp.toScreenX(s.x1()), vp.toScreenY(s.y1()), vp.toScreenX(s.x2()), vp.toScreenY(s.y2()));
  }

  /**
   * Draws one object.
   *
   * @param dx shift in mm (for previews while dragging; 0 otherwise)
   * @param dy shift in mm
   */
  public void drawObject(
      GraphicsContext gc,
      Viewport vp,
      ArMapObject o,
      boolean selected,
      boolean label,
      double dx,
      double dy) {
    ArMapObject obj = (dx == 0 && dy == 0) ? o : MapGeometry.translate(o, dx, dy);
    ObjectKind kind = ObjectKind.of(obj.type());
    if (obj.hasFromTo()) {
      drawFromTo(gc, vp, obj, kind, selected);
      return;
    }
    double x = vp.toScreenX(obj.pose().x());
    double y = vp.toScreenY(obj.pose().y());
    if (x < -60 || y < -60 || x > vp.width() + 60 || y > vp.height() + 60) {
      return;
    }
    Color c = colorOf(kind);
    gc.setLineWidth(2);
    gc.setStroke(selected ? SELECTION : c);
    gc.setFill(selected ? SELECTION : c);
    if (kind == ObjectKind.HOME) {
      gc.fillRect(x - 6, y - 6, 12, 12);
    } else if (kind == ObjectKind.DOCK) {
      gc.fillPolygon(new double[] {x - 7, x + 7, x}, new double[] {y + 6, y + 6, y - 7}, 3);
    } else if (kind == null) {
      gc.fillPolygon(new double[] {x - 6, x, x + 6, x}, new double[] {y, y - 6, y, y + 6}, 4);
    } else {
      gc.strokeOval(x - 6, y - 6, 12, 12);
      gc.fillOval(x - 2.5, y - 2.5, 5, 5);
    }
    if (kind != null && kind.hasHeading()) {
      double r = Math.toRadians(obj.pose().th());
      double ex = x + 18 * Math.cos(r);
      double ey = y - 18 * Math.sin(r);
      gc.strokeLine(x, y, ex, ey);
      double a = Math.atan2(ey - y, ex - x);
      gc.strokeLine(ex, ey, ex - 6 * Math.cos(a - 0.5), ey - 6 * Math.sin(a - 0.5));
      gc.strokeLine(ex, ey, ex - 6 * Math.cos(a + 0.5), ey - 6 * Math.sin(a + 0.5));
    }
    if (label && !obj.name().isEmpty()) {
      gc.setFont(font);
      gc.setTextAlign(TextAlignment.LEFT);
      gc.setTextBaseline(VPos.CENTER);
      gc.setFill(Color.WHITE);
      gc.fillText(obj.name(), x + 10 + 0.8, y + 0.8);
      gc.setFill(selected ? SELECTION : Color.web("#202020"));
      gc.fillText(obj.name(), x + 10, y);
    }
  }

  private void drawFromTo(
      GraphicsContext gc, Viewport vp, ArMapObject o, ObjectKind kind, boolean selected) {
    List<ArLineSegment> segs = o.getFromToSegments();
    double[] b = bounds(segs);
    if (!vp.intersects(b[0], b[1], b[2], b[3])) {
      return;
    }
    boolean forbidden = kind == ObjectKind.FORBIDDEN_AREA || kind == ObjectKind.FORBIDDEN_LINE;
    Color c = forbidden ? FORBIDDEN : OTHER;
    if (o.isAreaType()) {
      double[] xs = new double[4];
      double[] ys = new double[4];
      for (int i = 0; i < 4; i++) {
        xs[i] = vp.toScreenX(segs.get(i).x1());
        ys[i] = vp.toScreenY(segs.get(i).y1());
      }
      gc.setFill(forbidden ? FORBIDDEN_FILL : OTHER_FILL);
      gc.fillPolygon(xs, ys, 4);
      gc.setStroke(selected ? SELECTION : c);
      gc.setLineWidth(selected ? 3 : 1.5);
      gc.strokePolygon(xs, ys, 4);
      if (selected) {
        for (int i = 0; i < 4; i++) {
          handle(gc, xs[i], ys[i]);
        }
        double[] h = rotationHandle(vp, o);
        double[] top = topMiddle(vp, o);
        gc.setStroke(SELECTION);
        gc.setLineWidth(1);
        gc.strokeLine(top[0], top[1], h[0], h[1]);
        gc.setFill(Color.WHITE);
        gc.fillOval(h[0] - 5, h[1] - 5, 10, 10);
        gc.strokeOval(h[0] - 5, h[1] - 5, 10, 10);
      }
    } else {
      ArLineSegment s = segs.get(0);
      gc.setStroke(selected ? SELECTION : c);
      gc.setLineWidth(selected ? 4 : 2.5);
      double x1 = vp.toScreenX(s.x1());
      double y1 = vp.toScreenY(s.y1());
      double x2 = vp.toScreenX(s.x2());
      double y2 = vp.toScreenY(s.y2());
      gc.strokeLine(x1, y1, x2, y2);
      if (selected) {
        handle(gc, x1, y1);
        handle(gc, x2, y2);
      }
    }
  }

  /** Screen position of the middle of an area's top edge (corners 2 and 3). */
  static double[] topMiddle(Viewport vp, ArMapObject area) {
    double[] c = MapGeometry.corners(area);
    return new double[] {vp.toScreenX((c[4] + c[6]) / 2), vp.toScreenY((c[5] + c[7]) / 2)};
  }

  /** Screen position of a selected area's rotation handle: 24 px beyond its top edge. */
  public static double[] rotationHandle(Viewport vp, ArMapObject area) {
    double[] top = topMiddle(vp, area);
    double[] mid = MapGeometry.center(area);
    double cx = vp.toScreenX(mid[0]);
    double cy = vp.toScreenY(mid[1]);
    double dx = top[0] - cx;
    double dy = top[1] - cy;
    double len = Math.hypot(dx, dy);
    if (len < 1e-9) {
      double r = Math.toRadians(area.pose().th());
      return new double[] {cx - 24 * Math.sin(r), cy - 24 * Math.cos(r)};
    }
    return new double[] {top[0] + 24 * dx / len, top[1] + 24 * dy / len};
  }

  private static void handle(GraphicsContext gc, double x, double y) {
    gc.setFill(Color.WHITE);
    gc.fillRect(x - 3.5, y - 3.5, 7, 7);
    gc.setStroke(SELECTION);
    gc.setLineWidth(1);
    gc.strokeRect(x - 3.5, y - 3.5, 7, 7);
  }

  private static double[] bounds(List<ArLineSegment> segs) {
    double[] b = {
      Double.POSITIVE_INFINITY,
      Double.POSITIVE_INFINITY,
      Double.NEGATIVE_INFINITY,
      Double.NEGATIVE_INFINITY
    };
    for (ArLineSegment s : segs) {
      b[0] = Math.min(b[0], Math.min(s.x1(), s.x2()));
      b[1] = Math.min(b[1], Math.min(s.y1(), s.y2()));
      b[2] = Math.max(b[2], Math.max(s.x1(), s.x2()));
      b[3] = Math.max(b[3], Math.max(s.y1(), s.y2()));
    }
    return b;
  }

  static Color colorOf(ObjectKind kind) {
    if (kind == null) {
      return OTHER;
    }
    return switch (kind) {
      case GOAL, GOAL_WITH_HEADING -> GOAL;
      case HOME -> HOME;
      case DOCK -> DOCK;
      case FORBIDDEN_LINE, FORBIDDEN_AREA -> FORBIDDEN;
    };
  }

  private void drawScaleBar(GraphicsContext gc, Viewport vp) {
    double target = 120 / vp.scale();
    double mm = Math.pow(10, Math.floor(Math.log10(target)));
    if (mm * 5 <= target) {
      mm *= 5;
    } else if (mm * 2 <= target) {
      mm *= 2;
    }
    double len = mm * vp.scale();
    double x = 12;
    double y = vp.height() - 14;
    gc.setStroke(Color.web("#303030"));
    gc.setLineWidth(2);
    gc.strokeLine(x, y, x + len, y);
    gc.strokeLine(x, y - 4, x, y + 4);
    gc.strokeLine(x + len, y - 4, x + len, y + 4);
    gc.setFont(font);
    gc.setFill(Color.web("#303030"));
    gc.setTextAlign(TextAlignment.LEFT);
    gc.setTextBaseline(VPos.BOTTOM);
    gc.fillText(formatLength(mm), x, y - 5);
  }

  /** "250 mm", "5 m", "1.5 km", "12.34 m". */
  public static String formatLength(double mm) {
    if (Math.abs(mm) >= 1_000_000) {
      return trim(mm / 1_000_000) + " km";
    }
    if (Math.abs(mm) >= 1000) {
      return trim(mm / 1000) + " m";
    }
    if (Math.abs(mm) < 10) {
      return trim(mm) + " mm";
    }
    return String.format(Locale.ROOT, "%.0f mm", mm);
  }

  private static String trim(double v) {
    String s = String.format(Locale.ROOT, "%.2f", v);
    return s.replaceAll("\\.?0+$", "");
  }
}
