package org.jaria.apps.monitor;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.ToDoubleFunction;
import javafx.geometry.VPos;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import javafx.scene.text.Font;
import javafx.scene.text.TextAlignment;
import org.jaria.apps.fx.LabelPlacer;
import org.jaria.apps.fx.TextWidths;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMapObject;
import org.jaria.net.data.PathSnapshot;
import org.jaria.net.data.Points;
import org.jaria.net.data.RangeReadings;
import org.jaria.net.data.RobotUpdate;
import org.jaria.net.data.SensorReadings;

/**
 * Draws what the monitor knows: the map (points, lines, goals, forbidden areas), the localization's
 * particles, the planned path and the local planner's search area, the sonar readings, and the
 * robot at its pose. JavaFX thread only.
 */
final class MonitorRenderer {

  static final Color BACKGROUND = Color.WHITE;
  static final Color WALL = Color.web("#202020");
  static final Color GOAL = Color.web("#1a9e3a");
  static final Color HOME = Color.web("#1f5fd0");
  static final Color FORBIDDEN = Color.web("#d62020");
  static final Color FORBIDDEN_FILL = Color.web("#d62020", 0.15);
  static final Color PARTICLE = Color.web("#7b3fc4", 0.55);
  static final Color PATH = Color.web("#1e78ff");
  static final Color SEARCH = Color.web("#1e78ff", 0.12);
  static final Color SONAR = Color.web("#e07000");
  static final Color ROBOT = Color.web("#c0392b");
  static final Color ROBOT_FILL = Color.web("#c0392b", 0.25);
  static final Color GHOST = Color.web("#1e78ff", 0.5);
  private static final int POINT_ARGB = 0xFF303030;

  /** Which layers to draw. */
  record Layers(boolean sonar, boolean particles, boolean path) {}

  private final Font font = Font.font("System", 11);
  private final TextWidths widths = new TextWidths(font);

  /** A name's height in pixels (the font's size and a little room). */
  private static final double LABEL_HEIGHT = 14;

  void render(GraphicsContext gc, Viewport vp, MonitorState s, Layers layers, ArPose ghost) {
    gc.setFill(BACKGROUND);
    gc.fillRect(0, 0, vp.width(), vp.height());
    MonitorState.MapView m = s.map;
    if (m != null) {
      drawMap(gc, vp, m);
    }
    if (layers.particles() && s.particles != null) {
      drawParticles(gc, vp, s.particles.samples());
    }
    PathSnapshot path = s.path;
    if (layers.path() && path != null) {
      drawPath(gc, vp, path);
    }
    SensorReadings sensors = s.sensors;
    if (layers.sonar() && sensors != null) {
      gc.setFill(SONAR);
      for (RangeReadings r : sensors.devices()) {
        if (r.device().toLowerCase(java.util.Locale.ROOT).contains("sonar")) {
          Points p = r.current();
          for (int i = 0; i < p.size(); i++) {
            gc.fillOval(vp.toScreenX(p.x(i)) - 2.5, vp.toScreenY(p.y(i)) - 2.5, 5, 5);
          }
        }
      }
    }
    RobotUpdate u = s.robot;
    // Drawings also come from servers without a robot (ARIA's drawingsExample): arrows then point
    // at the map's origin.
    DrawingsRenderer.draw(
        gc, vp, s.drawings, s.drawingPoints, u != null ? u.x() : 0, u != null ? u.y() : 0);
    double radius = s.physical != null ? s.physical.radius() : 250;
    if (u != null) {
      drawRobot(gc, vp, u.getPose(), radius, ROBOT, ROBOT_FILL);
    }
    if (ghost != null) {
      drawRobot(gc, vp, ghost, radius, GHOST, GHOST);
    }
  }

  private void drawMap(GraphicsContext gc, Viewport vp, MonitorState.MapView m) {
    gc.drawImage(
        m.points().render(vp, POINT_ARGB, null, 0, Math.max(1, m.map().getResolution())), 0, 0);
    gc.setStroke(WALL);
    gc.setLineWidth(vp.scale() > 0.2 ? 2 : 1);
    for (ArLineSegment l : m.map().getLines()) {
      if (vp.intersects(l.x1(), l.y1(), l.x2(), l.y2())) {
        gc.strokeLine(
            vp.toScreenX(l.x1()), vp.toScreenY(l.y1()), vp.toScreenX(l.x2()), vp.toScreenY(l.y2()));
      }
    }
    for (ArMapObject o : m.map().getMapObjects()) {
      drawObject(gc, vp, o);
    }
    gc.setFont(font);
    gc.setTextAlign(TextAlignment.LEFT);
    gc.setTextBaseline(VPos.CENTER);
    for (LabelPlacer.Placed p :
        placeLabels(m.map().getMapObjects(), m.map().getLines(), vp, widths::of, LABEL_HEIGHT)) {
      ArMapObject o = (ArMapObject) p.label().tag();
      gc.setFill(Color.WHITE);
      gc.fillText(p.label().text(), p.left() + 0.8, p.centerY() + 0.8);
      gc.setFill(o.isGoal() ? GOAL : HOME);
      gc.fillText(p.label().text(), p.left(), p.centerY());
    }
  }

  /**
   * Where the names of goals, the home and docks go on the picture {@code vp} shows: beside their
   * markers, over no marker or other name, never past the picture's edge, and across a wall only
   * where no side is clear (the dock by the office map's east wall puts its name on the left).
   */
  static List<LabelPlacer.Placed> placeLabels(
      List<ArMapObject> objects,
      List<ArLineSegment> walls,
      Viewport vp,
      ToDoubleFunction<String> textWidth,
      double height) {
    List<LabelPlacer.Label> labels = new ArrayList<>();
    double[] unnamed = new double[2 * objects.size()];
    int n = 0;
    for (ArMapObject o : objects) {
      if (!hasMarker(o)) {
        continue;
      }
      double x = vp.toScreenX(o.pose().x());
      double y = vp.toScreenY(o.pose().y());
      if (o.name().isEmpty()) {
        unnamed[n++] = x;
        unnamed[n++] = y;
      } else {
        labels.add(
            new LabelPlacer.Label(x, y, textWidth.applyAsDouble(o.name()), height, o.name(), o));
      }
    }
    double[] lines = new double[4 * walls.size()];
    int k = 0;
    for (ArLineSegment s : walls) {
      lines[k++] = vp.toScreenX(s.x1());
      lines[k++] = vp.toScreenY(s.y1());
      lines[k++] = vp.toScreenX(s.x2());
      lines[k++] = vp.toScreenY(s.y2());
    }
    return LabelPlacer.place(labels, Arrays.copyOf(unnamed, n), lines, vp.width(), vp.height());
  }

  /** Goals, the home and docks have a marker; forbidden lines and areas are drawn as shapes. */
  private static boolean hasMarker(ArMapObject o) {
    String type = o.type();
    return !type.startsWith("Forbidden")
        && (o.isGoal() || type.equalsIgnoreCase("RobotHome") || type.equalsIgnoreCase("Dock"));
  }

  private void drawObject(GraphicsContext gc, Viewport vp, ArMapObject o) {
    String type = o.type();
    if (type.startsWith("Forbidden")) {
      gc.setStroke(FORBIDDEN);
      gc.setLineWidth(2);
      if (o.isAreaType()) {
        var segs = o.getFromToSegments();
        double[] xs = new double[segs.size()];
        double[] ys = new double[segs.size()];
        for (int i = 0; i < segs.size(); i++) {
          xs[i] = vp.toScreenX(segs.get(i).x1());
          ys[i] = vp.toScreenY(segs.get(i).y1());
        }
        gc.setFill(FORBIDDEN_FILL);
        gc.fillPolygon(xs, ys, xs.length);
        gc.strokePolygon(xs, ys, xs.length);
      } else if (o.isLineType()) {
        ArLineSegment s = o.getFromToSegment();
        gc.strokeLine(
            vp.toScreenX(s.x1()), vp.toScreenY(s.y1()), vp.toScreenX(s.x2()), vp.toScreenY(s.y2()));
      }
      return;
    }
    if (!hasMarker(o)) {
      return;
    }
    boolean goal = o.isGoal();
    double x = vp.toScreenX(o.pose().x());
    double y = vp.toScreenY(o.pose().y());
    gc.setStroke(goal ? GOAL : HOME);
    gc.setFill(goal ? GOAL : HOME);
    gc.setLineWidth(2);
    gc.strokeOval(x - 6, y - 6, 12, 12);
    gc.fillOval(x - 2, y - 2, 4, 4);
  }

  private static void drawParticles(GraphicsContext gc, Viewport vp, Points p) {
    gc.setStroke(PARTICLE);
    gc.setLineWidth(1);
    double len = Math.max(4, 150 * vp.scale());
    for (int i = 0; i < p.size(); i++) {
      double x = vp.toScreenX(p.x(i));
      double y = vp.toScreenY(p.y(i));
      double th = Math.toRadians(p.th(i));
      gc.strokeLine(x, y, x + len * Math.cos(th), y - len * Math.sin(th));
    }
  }

  private static void drawPath(GraphicsContext gc, Viewport vp, PathSnapshot path) {
    Points area = path.searchArea();
    if (area.size() >= 3) {
      double[] xs = new double[area.size()];
      double[] ys = new double[area.size()];
      for (int i = 0; i < area.size(); i++) {
        xs[i] = vp.toScreenX(area.x(i));
        ys[i] = vp.toScreenY(area.y(i));
      }
      gc.setFill(SEARCH);
      gc.fillPolygon(xs, ys, xs.length);
    }
    Points p = path.path();
    if (p.size() >= 2) {
      double[] xs = new double[p.size()];
      double[] ys = new double[p.size()];
      for (int i = 0; i < p.size(); i++) {
        xs[i] = vp.toScreenX(p.x(i));
        ys[i] = vp.toScreenY(p.y(i));
      }
      gc.setStroke(PATH);
      gc.setLineWidth(2);
      gc.strokePolyline(xs, ys, xs.length);
    }
    ArPose g = path.goal();
    if (g != null
        && (path.state().equals("PLANNING_PATH") || path.state().equals("MOVING_TO_GOAL"))) {
      double x = vp.toScreenX(g.x());
      double y = vp.toScreenY(g.y());
      gc.setStroke(PATH);
      gc.setLineWidth(2);
      gc.strokeLine(x - 7, y - 7, x + 7, y + 7);
      gc.strokeLine(x - 7, y + 7, x + 7, y - 7);
    }
  }

  private static void drawRobot(
      GraphicsContext gc, Viewport vp, ArPose p, double radius, Color stroke, Color fill) {
    double x = vp.toScreenX(p.x());
    double y = vp.toScreenY(p.y());
    double r = Math.max(5, radius * vp.scale());
    gc.setFill(fill);
    gc.fillOval(x - r, y - r, 2 * r, 2 * r);
    gc.setStroke(stroke);
    gc.setLineWidth(2);
    gc.strokeOval(x - r, y - r, 2 * r, 2 * r);
    double th = Math.toRadians(p.th());
    gc.strokeLine(x, y, x + r * Math.cos(th), y - r * Math.sin(th));
  }
}
