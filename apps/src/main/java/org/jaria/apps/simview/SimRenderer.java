package org.jaria.apps.simview;

import java.util.List;
import java.util.Locale;
import java.util.Map;
import javafx.geometry.VPos;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import javafx.scene.shape.ArcType;
import javafx.scene.text.Font;
import javafx.scene.text.TextAlignment;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimLaserScan;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.world.WorldMap;

/**
 * Draws a simulated world: the map's walls and points, injected obstacles, and every robot with its
 * footprint, sonar cones and ranges, laser scan, camera field of view, and its odometry pose next
 * to its true pose. Draws what is in view only. JavaFX thread.
 */
public final class SimRenderer {

  /**
   * What to draw besides map and robots.
   *
   * @param sonar sonar cones and ranges
   * @param laser laser scans
   * @param camera the camera's field of view
   * @param odometry where odometry thinks each robot is
   * @param grid a 1 m grid
   */
  public record Layers(
      boolean sonar, boolean laser, boolean camera, boolean odometry, boolean grid) {
    /** Everything. */
    public static final Layers ALL = new Layers(true, true, true, true, true);
  }

  /**
   * A camera on a robot, as drawn: where it looks relative to the robot and how wide it sees.
   *
   * @param panDeg pan, degrees (+ right, ARIA's sign)
   * @param fovDeg horizontal field of view, degrees
   */
  public record CameraView(double panDeg, double fovDeg) {
    /** A Canon VC-C4 looking straight ahead, zoomed out (what a Pioneer usually carries). */
    public static final CameraView DEFAULT = new CameraView(0, CAMERA_FOV_DEG);
  }

  /** Horizontal field of view of the Canon VC-C4 a Pioneer carries, degrees (wide end). */
  public static final double CAMERA_FOV_DEG = 47.5;

  /** How far the drawn field of view reaches, mm. */
  public static final double CAMERA_RANGE_MM = 3000;

  static final Color WALL = Color.web("#202020");
  static final Color OBSTACLE = Color.web("#8b4513");
  static final Color ROBOT = Color.web("#c0392b");
  static final Color ODOMETRY = Color.web("#2c6fd1");
  static final Color SONAR = Color.web("#f0a020", 0.16);
  static final Color SONAR_EDGE = Color.web("#d08000", 0.6);
  static final Color LASER = Color.web("#1a9e3a", 0.8);
  static final Color CAMERA = Color.web("#8a2be2", 0.8);
  static final Color SELECTED = Color.web("#1e78ff");

  private final Font font = Font.font("System", 11);

  /**
   * Draws the world.
   *
   * @param points the map's points (may be null)
   * @param selectedObstacle id of an obstacle being dragged (drawn at {@code dragDx, dragDy}), or
   *     -1
   * @param objects the coloured objects cameras see (balls, boxes), drawn in their colours
   * @param cameras the cameras of robots that carry one, by robot index; other robots are drawn
   *     with a {@link CameraView#DEFAULT} field of view
   */
  public void render(
      GraphicsContext gc,
      Viewport vp,
      WorldMap map,
      PointLayer points,
      SimSnapshot snap,
      Layers layers,
      int selectedObstacle,
      double dragDx,
      double dragDy,
      List<ColoredObject> objects,
      Map<Integer, CameraView> cameras) {
    gc.setFill(Color.WHITE);
    gc.fillRect(0, 0, vp.width(), vp.height());
    if (layers.grid()) {
      grid(gc, vp);
    }
    if (points != null) {
      gc.drawImage(points.render(vp, 0xFF404040, null, 0, 20), 0, 0);
    }
    gc.setStroke(WALL);
    gc.setLineWidth(vp.scale() > 0.2 ? 2 : 1);
    for (ArLineSegment s : map.lines()) {
      line(gc, vp, s, 0, 0);
    }
    for (SimObstacle o : snap.obstacles()) {
      boolean sel = o.id() == selectedObstacle;
      gc.setStroke(sel ? SELECTED : OBSTACLE);
      gc.setLineWidth(3);
      for (ArLineSegment s : o.segments()) {
        line(gc, vp, s, sel ? dragDx : 0, sel ? dragDy : 0);
      }
    }
    for (ColoredObject o : objects) {
      coloredObject(gc, vp, o);
    }
    for (SimSnapshot.RobotView r : snap.robots()) {
      robot(gc, vp, r, layers, cameras.getOrDefault(r.index(), CameraView.DEFAULT));
    }
    gc.setFont(font);
    gc.setFill(Color.web("#303030"));
    gc.setTextAlign(TextAlignment.LEFT);
    gc.setTextBaseline(VPos.BOTTOM);
    gc.fillText(
        String.format(Locale.ROOT, "t = %.1f s", snap.simTimeNanos() / 1e9), 10, vp.height() - 8);
  }

  // 1-pixel fills rather than strokes: far cheaper in the software renderer (see MapRenderer).
  private static void grid(GraphicsContext gc, Viewport vp) {
    double step = 1000;
    while (step * vp.scale() < 8) {
      step *= 10;
    }
    gc.setFill(Color.web("#eceff4"));
    for (double x = Math.floor(vp.minVisibleX() / step) * step; x <= vp.maxVisibleX(); x += step) {
      gc.fillRect(Math.floor(vp.toScreenX(x)), 0, 1, vp.height());
    }
    for (double y = Math.floor(vp.minVisibleY() / step) * step; y <= vp.maxVisibleY(); y += step) {
      gc.fillRect(0, Math.floor(vp.toScreenY(y)), vp.width(), 1);
    }
  }

  private static void line(GraphicsContext gc, Viewport vp, ArLineSegment s, double dx, double dy) {
    if (!vp.intersects(s.x1() + dx, s.y1() + dy, s.x2() + dx, s.y2() + dy)) {
      return;
    }
    gc.strokeLine(
        vp.toScreenX(s.x1() + dx),
        vp.toScreenY(s.y1() + dy),
        vp.toScreenX(s.x2() + dx),
        vp.toScreenY(s.y2() + dy));
  }

  private static void coloredObject(GraphicsContext gc, Viewport vp, ColoredObject o) {
    double reach = Math.max(o.width(), o.depth());
    if (!vp.intersects(o.x() - reach, o.y() - reach, o.x() + reach, o.y() + reach)) {
      return;
    }
    int c = o.rgb();
    gc.setFill(Color.rgb((c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF));
    gc.setStroke(Color.web("#202020"));
    gc.setLineWidth(1);
    double x = vp.toScreenX(o.x());
    double y = vp.toScreenY(o.y());
    if (o.shape() == ColoredObject.Shape.CYLINDER) {
      double r = Math.max(2.5, o.width() / 2 * vp.scale());
      gc.fillOval(x - r, y - r, 2 * r, 2 * r);
      gc.strokeOval(x - r, y - r, 2 * r, 2 * r);
      return;
    }
    double a = Math.toRadians(o.th());
    double[] xs = new double[4];
    double[] ys = new double[4];
    double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; i++) {
      double lx = corners[i][0] * o.width() / 2;
      double ly = corners[i][1] * o.depth() / 2;
      xs[i] = vp.toScreenX(o.x() + lx * Math.cos(a) - ly * Math.sin(a));
      ys[i] = vp.toScreenY(o.y() + lx * Math.sin(a) + ly * Math.cos(a));
    }
    gc.fillPolygon(xs, ys, 4);
    gc.strokePolygon(xs, ys, 4);
  }

  private void robot(
      GraphicsContext gc, Viewport vp, SimSnapshot.RobotView r, Layers layers, CameraView cam) {
    ArPose p = r.truePose();
    if (layers.sonar()) {
      for (SimSnapshot.SonarView s : r.sonar()) {
        sonar(gc, vp, s);
      }
    }
    if (layers.laser() && r.laser() != null) {
      laser(gc, vp, r.laser());
    }
    if (layers.camera()) {
      camera(gc, vp, p, cam);
    }
    if (layers.odometry()) {
      ArPose o = r.odometryPose();
      gc.setStroke(ODOMETRY);
      gc.setLineWidth(1.5);
      gc.setLineDashes(5, 4);
      gc.strokePolygon(
          xs(vp, shifted(r.footprint(), p, o)), ys(vp, shifted(r.footprint(), p, o)), 4);
      gc.setLineDashes();
      heading(gc, vp, o, ODOMETRY);
    }
    List<ArPose> fp = r.footprint();
    gc.setFill(ROBOT.deriveColor(0, 1, 1, 0.35));
    gc.fillPolygon(xs(vp, fp), ys(vp, fp), fp.size());
    gc.setStroke(r.stallAndBumpers() != 0 ? Color.ORANGERED : ROBOT);
    gc.setLineWidth(2);
    gc.strokePolygon(xs(vp, fp), ys(vp, fp), fp.size());
    heading(gc, vp, p, ROBOT);
    gc.setFont(font);
    gc.setFill(Color.web("#202020"));
    gc.setTextAlign(TextAlignment.CENTER);
    gc.setTextBaseline(VPos.TOP);
    gc.fillText(r.name(), vp.toScreenX(p.x()), vp.toScreenY(p.y()) + 14);
  }

  /** The footprint as it would be if the robot stood at {@code to} instead of {@code from}. */
  static List<ArPose> shifted(List<ArPose> fp, ArPose from, ArPose to) {
    double d = Math.toRadians(to.th() - from.th());
    double c = Math.cos(d);
    double s = Math.sin(d);
    return fp.stream()
        .map(
            q -> {
              double x = q.x() - from.x();
              double y = q.y() - from.y();
              return new ArPose(to.x() + x * c - y * s, to.y() + x * s + y * c);
            })
        .toList();
  }

  private static double[] xs(Viewport vp, List<ArPose> pts) {
    double[] a = new double[pts.size()];
    for (int i = 0; i < a.length; i++) {
      a[i] = vp.toScreenX(pts.get(i).x());
    }
    return a;
  }

  private static double[] ys(Viewport vp, List<ArPose> pts) {
    double[] a = new double[pts.size()];
    for (int i = 0; i < a.length; i++) {
      a[i] = vp.toScreenY(pts.get(i).y());
    }
    return a;
  }

  private static void heading(GraphicsContext gc, Viewport vp, ArPose p, Color c) {
    double x = vp.toScreenX(p.x());
    double y = vp.toScreenY(p.y());
    double len = Math.max(10, 250 * vp.scale());
    double r = Math.toRadians(p.th());
    gc.setStroke(c);
    gc.setLineWidth(2);
    gc.strokeLine(x, y, x + len * Math.cos(r), y - len * Math.sin(r));
  }

  private static void sonar(GraphicsContext gc, Viewport vp, SimSnapshot.SonarView s) {
    // No echo (or never fired: sonar only fires while a client has the robot open): nothing to
    // show, as a drawn 5 m cone would hide the map.
    if (s.rangeMm() <= 0 || !s.echo()) {
      return;
    }
    double r = s.rangeMm() * vp.scale();
    double x = vp.toScreenX(s.x());
    double y = vp.toScreenY(s.y());
    if (!vp.intersects(
        s.x() - s.rangeMm(), s.y() - s.rangeMm(), s.x() + s.rangeMm(), s.y() + s.rangeMm())) {
      return;
    }
    double start = s.thDeg() - s.coneDeg() / 2;
    gc.setFill(SONAR);
    gc.fillArc(x - r, y - r, 2 * r, 2 * r, start, s.coneDeg(), ArcType.ROUND);
    gc.setStroke(SONAR_EDGE);
    gc.setLineWidth(2);
    gc.strokeArc(x - r, y - r, 2 * r, 2 * r, start, s.coneDeg(), ArcType.OPEN);
  }

  private static void laser(GraphicsContext gc, Viewport vp, SimLaserScan scan) {
    ArPose o = scan.origin();
    double ox = vp.toScreenX(o.x());
    double oy = vp.toScreenY(o.y());
    gc.setStroke(LASER.deriveColor(0, 1, 1, 0.25));
    gc.setLineWidth(1);
    gc.setFill(LASER);
    for (int k = 0; k < scan.size(); k++) {
      double a = Math.toRadians(o.th() + scan.startDeg() + k * scan.incrementDeg());
      double d = scan.range(k);
      double hx = vp.toScreenX(o.x() + d * Math.cos(a));
      double hy = vp.toScreenY(o.y() + d * Math.sin(a));
      if (k % 4 == 0) {
        gc.strokeLine(ox, oy, hx, hy);
      }
      gc.fillRect(hx - 1, hy - 1, 2.5, 2.5);
    }
  }

  private static void camera(GraphicsContext gc, Viewport vp, ArPose p, CameraView cam) {
    double x = vp.toScreenX(p.x());
    double y = vp.toScreenY(p.y());
    double r = CAMERA_RANGE_MM * vp.scale();
    double half = Math.toRadians(cam.fovDeg() / 2);
    double headingDeg = p.th() - cam.panDeg();
    double th = Math.toRadians(headingDeg);
    gc.setStroke(CAMERA);
    gc.setLineWidth(1.2);
    gc.setLineDashes(3, 3);
    gc.strokeLine(x, y, x + r * Math.cos(th + half), y - r * Math.sin(th + half));
    gc.strokeLine(x, y, x + r * Math.cos(th - half), y - r * Math.sin(th - half));
    gc.strokeArc(
        x - r, y - r, 2 * r, 2 * r, headingDeg - cam.fovDeg() / 2, cam.fovDeg(), ArcType.OPEN);
    gc.setLineDashes();
  }
}
