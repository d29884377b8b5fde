package org.jaria.apps.simview;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import javafx.scene.Cursor;
import javafx.scene.canvas.Canvas;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.MouseButton;
import javafx.scene.input.MouseEvent;
import javafx.scene.input.ScrollEvent;
import javafx.scene.layout.Region;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.sim.SimObstacle;
import org.jaria.sim.SimSnapshot;
import org.jaria.sim.camera.ColoredObject;
import org.jaria.sim.camera.SimCamera;
import org.jaria.sim.world.WorldMap;

/**
 * The simulator view's drawing area. With the Move tool, drag an obstacle, a coloured object (a
 * ball the camera sees) or a robot to move it (empty space pans); with the Place tool, press where
 * the selected robot should stand and drag towards where it should face; with the Box tool, drag a
 * rectangle to add a box. The wheel zooms, the middle and right buttons pan.
 */
final class SimCanvas extends Region {

  /** The mouse tools. */
  enum Tool {
    /** Drag obstacles and robots; pan elsewhere. */
    MOVE,
    /** Place the selected robot (press: position, drag: heading). */
    PLACE,
    /** Drag a rectangle to add a box obstacle. */
    BOX
  }

  private final Canvas canvas = new Canvas(10, 10);
  private final Viewport vp = new Viewport();
  private boolean fitPending;
  private double[] fitBox;
  private final SimRenderer renderer = new SimRenderer();
  private final SimController controller;
  private final WorldMap map;
  private final PointLayer points;
  private SimRenderer.Layers layers = SimRenderer.Layers.ALL;
  private Tool tool = Tool.MOVE;
  private int robotIndex;
  private SimSnapshot snapshot;
  private final Map<Integer, ArTransform> odometryToWorld = new HashMap<>();
  // The last robot views drawn, to notice odometry being reset (a new session, a client's SETO).
  private final Map<Integer, SimSnapshot.RobotView> lastViews = new HashMap<>();
  // Cameras shown with their real pan and field of view; registered from any thread.
  private final Map<Integer, SimCamera> cameras = new ConcurrentHashMap<>();
  private List<ColoredObject> objects = List.of();
  private ColoredObject dragObject;
  private Consumer<String> status = s -> {};
  private Runnable changed = () -> {};
  // Told when robots arrive or leave (a robot factory's robot lives as long as its client).
  private Consumer<List<SimSnapshot.RobotView>> robotsChanged = r -> {};
  private Set<Integer> shownRobots = Set.of();

  private boolean panning;
  private double lastX;
  private double lastY;
  private double[] start;
  private double[] current;
  private SimObstacle dragObstacle;
  private int dragRobot = -1;
  private double dragHeading = Double.NaN;

  SimCanvas(SimController controller) {
    this.controller = controller;
    this.map = controller.world().getMap();
    this.points = new PointLayer(map.pointX(), map.pointY());
    getChildren().add(canvas);
    setMinSize(100, 100);
    setPrefSize(900, 650);
    setFocusTraversable(true);
    addEventHandler(MouseEvent.MOUSE_PRESSED, this::pressed);
    addEventHandler(MouseEvent.MOUSE_DRAGGED, this::dragged);
    addEventHandler(MouseEvent.MOUSE_RELEASED, this::released);
    addEventHandler(ScrollEvent.SCROLL, this::scrolled);
    snapshot = aligned(controller.world().snapshot());
    objects = controller.world().coloredObjects().list();
  }

  @Override
  protected void layoutChildren() {
    double w = Math.max(1, getWidth());
    double h = Math.max(1, getHeight());
    if (canvas.getWidth() != w || canvas.getHeight() != h) {
      double cx = vp.centerX();
      double cy = vp.centerY();
      canvas.setWidth(w);
      canvas.setHeight(h);
      vp.setSize(w, h);
      vp.setCenter(cx, cy);
      if (fitPending) {
        fitTo(fitBox);
      }
      paint();
    }
  }

  Viewport viewport() {
    return vp;
  }

  void setTool(Tool t) {
    tool = t;
    setCursor(t == Tool.MOVE ? Cursor.DEFAULT : Cursor.CROSSHAIR);
  }

  void setRobotIndex(int i) {
    robotIndex = i;
  }

  void setLayers(SimRenderer.Layers l) {
    layers = l;
    paint();
  }

  SimRenderer.Layers layers() {
    return layers;
  }

  void setStatusSink(Consumer<String> s) {
    status = s;
  }

  /** Called after the user changed the world (placed a robot, moved an obstacle). */
  void setChangeListener(Runnable r) {
    changed = r;
  }

  /**
   * Calls {@code r} with the robots of the newest snapshot whenever robots arrived or left since
   * the one before (on the JavaFX thread), and once now with the robots there are.
   */
  void setRobotsListener(Consumer<List<SimSnapshot.RobotView>> r) {
    robotsChanged = r;
    shownRobots = robotNumbers(snapshot);
    r.accept(snapshot.robots());
  }

  /** Zooms so the map and the robots fit. */
  void fit() {
    fitTo(null);
  }

  /** Zooms so the map box {x0, y0, x1, y1} fits (null: the map and the robots). */
  void fitTo(double[] box) {
    if (getWidth() < 2 || getHeight() < 2) {
      fitPending = true; // not laid out yet: fit once the view has its size
      fitBox = box;
      return;
    }
    fitPending = false;
    double[] b = box != null ? box : bounds();
    vp.fit(
        Math.min(b[0], b[2]), Math.min(b[1], b[3]), Math.max(b[0], b[2]), Math.max(b[1], b[3]), 10);
    paint();
  }

  void zoom(double f) {
    vp.zoomAt(f, vp.width() / 2, vp.height() / 2);
    paint();
  }

  private double[] bounds() {
    double x0 = Double.POSITIVE_INFINITY;
    double y0 = Double.POSITIVE_INFINITY;
    double x1 = Double.NEGATIVE_INFINITY;
    double y1 = Double.NEGATIVE_INFINITY;
    for (ArLineSegment s : map.lines()) {
      x0 = Math.min(x0, Math.min(s.x1(), s.x2()));
      y0 = Math.min(y0, Math.min(s.y1(), s.y2()));
      x1 = Math.max(x1, Math.max(s.x1(), s.x2()));
      y1 = Math.max(y1, Math.max(s.y1(), s.y2()));
    }
    int[] px = map.pointX();
    int[] py = map.pointY();
    for (int i = 0; i < px.length; i++) {
      x0 = Math.min(x0, px[i]);
      y0 = Math.min(y0, py[i]);
      x1 = Math.max(x1, px[i]);
      y1 = Math.max(y1, py[i]);
    }
    for (SimSnapshot.RobotView r : snapshot.robots()) {
      x0 = Math.min(x0, r.truePose().x() - 1000);
      y0 = Math.min(y0, r.truePose().y() - 1000);
      x1 = Math.max(x1, r.truePose().x() + 1000);
      y1 = Math.max(y1, r.truePose().y() + 1000);
    }
    if (x0 > x1) {
      return new double[] {-5000, -5000, 5000, 5000};
    }
    return new double[] {x0, y0, x1, y1};
  }

  /**
   * Lays each robot's odometry over the map from where it was in {@code start} (instead of where
   * the view first saw it).
   */
  void alignOdometry(SimSnapshot start) {
    odometryToWorld.clear();
    for (SimSnapshot.RobotView r : start.robots()) {
      odometryToWorld.put(r.index(), ArTransform.between(r.odometryPose(), r.truePose()));
    }
    refresh();
  }

  /** Takes a new snapshot of the world and draws it. */
  void refresh() {
    snapshot = aligned(controller.world().snapshot());
    objects = controller.world().coloredObjects().list();
    Set<Integer> live = robotNumbers(snapshot);
    if (!live.equals(shownRobots)) {
      shownRobots = live;
      robotsChanged.accept(snapshot.robots());
    }
    paint();
  }

  private static Set<Integer> robotNumbers(SimSnapshot s) {
    Set<Integer> numbers = new HashSet<>();
    for (SimSnapshot.RobotView r : s.robots()) {
      numbers.add(r.index());
    }
    return numbers;
  }

  /**
   * The robot numbers the view keeps something for (odometry alignment, last view, camera): only
   * robots in the last snapshot, so robots that come and go leave nothing behind.
   */
  Set<Integer> rememberedRobots() {
    Set<Integer> all = new HashSet<>(odometryToWorld.keySet());
    all.addAll(lastViews.keySet());
    all.addAll(cameras.keySet());
    return all;
  }

  /**
   * Draws {@code camera}'s real pan and field of view for robot {@code robotIndex} (instead of a
   * VC-C4 looking ahead). Any thread.
   */
  void attachCamera(int robotIndex, SimCamera camera) {
    cameras.put(robotIndex, camera);
  }

  /** Stops drawing {@code camera} (if it is still the one of robot {@code robotIndex}). */
  void detachCamera(int robotIndex, SimCamera camera) {
    cameras.remove(robotIndex, camera);
  }

  /** The cameras drawn with their real pan and field of view, by robot index. */
  Map<Integer, SimRenderer.CameraView> cameraViews() {
    Map<Integer, SimRenderer.CameraView> m = new HashMap<>();
    cameras.forEach((i, c) -> m.put(i, new SimRenderer.CameraView(c.getPan(), c.getFovDegrees())));
    return m;
  }

  /**
   * The snapshot with each robot's odometry pose laid over the map: odometry counts from its own
   * origin, so it is aligned with the true pose where the view first saw the robot (or where the
   * user last placed it); from then on the two drift apart as odometry errs.
   */
  private SimSnapshot aligned(SimSnapshot s) {
    List<SimSnapshot.RobotView> out = new ArrayList<>(s.robots().size());
    for (SimSnapshot.RobotView r : s.robots()) {
      SimSnapshot.RobotView last = lastViews.put(r.index(), r);
      if (last != null && odometryReset(last, r)) {
        odometryToWorld.remove(r.index());
      }
      ArTransform t =
          odometryToWorld.computeIfAbsent(
              r.index(), i -> ArTransform.between(r.odometryPose(), r.truePose()));
      out.add(
          new SimSnapshot.RobotView(
              r.index(),
              r.name(),
              r.subtype(),
              r.truePose(),
              t.doTransform(r.odometryPose()),
              r.footprint(),
              r.sonar(),
              r.laser(),
              r.stallAndBumpers(),
              r.vel(),
              r.rotVel(),
              r.motorsEnabled(),
              r.clientConnected(),
              r.sessionOpen()));
    }
    // Robot numbers are never reused: what is kept for a robot that left is never needed again.
    Set<Integer> live = robotNumbers(s);
    lastViews.keySet().retainAll(live);
    odometryToWorld.keySet().retainAll(live);
    cameras.keySet().retainAll(live);
    return new SimSnapshot(s.simTimeNanos(), out, s.obstacles());
  }

  /**
   * Whether the robot's odometry was set anew between two views rather than drifting: a client
   * opened a session (odometry starts at 0, 0, 0 wherever the robot stands) or set it (SETO,
   * ArRobot.moveTo), which shows as odometry jumping much further than the robot moved.
   */
  static boolean odometryReset(SimSnapshot.RobotView before, SimSnapshot.RobotView now) {
    if (now.sessionOpen() && !before.sessionOpen()) {
      return true;
    }
    double moved =
        Math.hypot(
            now.truePose().x() - before.truePose().x(), now.truePose().y() - before.truePose().y());
    double odoMoved =
        Math.hypot(
            now.odometryPose().x() - before.odometryPose().x(),
            now.odometryPose().y() - before.odometryPose().y());
    double turned = ArMath.subAngle(now.truePose().th(), before.truePose().th());
    double odoTurned = ArMath.subAngle(now.odometryPose().th(), before.odometryPose().th());
    // Real odometry errors are a few percent of the motion; a reset is a jump of metres or a
    // turn of tens of degrees the robot did not make.
    return Math.abs(odoMoved - moved) > 500 + 0.1 * moved
        || Math.abs(ArMath.subAngle(odoTurned, turned)) > 30;
  }

  /** The last snapshot drawn. */
  SimSnapshot snapshot() {
    return snapshot;
  }

  void paint() {
    GraphicsContext gc = canvas.getGraphicsContext2D();
    int sel = dragObstacle != null ? dragObstacle.id() : -1;
    double dx = dragObstacle != null ? current[0] - start[0] : 0;
    double dy = dragObstacle != null ? current[1] - start[1] : 0;
    List<ColoredObject> shown = objects;
    if (dragObject != null) {
      shown = new ArrayList<>(objects);
      shown.replaceAll(
          o ->
              o.id() == dragObject.id()
                  ? o.at(o.x() + current[0] - start[0], o.y() + current[1] - start[1])
                  : o);
    }
    renderer.render(gc, vp, map, points, snapshot, layers, sel, dx, dy, shown, cameraViews());
    overlay(gc);
  }

  private void overlay(GraphicsContext gc) {
    if (start == null) {
      return;
    }
    if (tool == Tool.BOX) {
      double x = Math.min(vp.toScreenX(start[0]), vp.toScreenX(current[0]));
      double y = Math.min(vp.toScreenY(start[1]), vp.toScreenY(current[1]));
      gc.setStroke(SimRenderer.OBSTACLE);
      gc.setLineDashes(4, 3);
      gc.setLineWidth(2);
      gc.strokeRect(
          x,
          y,
          Math.abs(vp.toScreenX(current[0]) - vp.toScreenX(start[0])),
          Math.abs(vp.toScreenY(current[1]) - vp.toScreenY(start[1])));
      gc.setLineDashes();
    } else if (tool == Tool.PLACE || dragRobot >= 0) {
      ArPose p = placement();
      double x = vp.toScreenX(p.x());
      double y = vp.toScreenY(p.y());
      double r = Math.max(6, 250 * vp.scale());
      gc.setStroke(SimRenderer.SELECTED);
      gc.setLineWidth(2);
      gc.strokeOval(x - r, y - r, 2 * r, 2 * r);
      double th = Math.toRadians(p.th());
      gc.strokeLine(x, y, x + r * 1.4 * Math.cos(th), y - r * 1.4 * Math.sin(th));
    }
  }

  private ArPose placement() {
    if (dragRobot >= 0) {
      ArPose was = robotPose(dragRobot);
      return new ArPose(was.x() + current[0] - start[0], was.y() + current[1] - start[1], was.th());
    }
    double th = Double.isNaN(dragHeading) ? robotPose(robotIndex).th() : dragHeading;
    return new ArPose(start[0], start[1], th);
  }

  private ArPose robotPose(int index) {
    for (SimSnapshot.RobotView r : snapshot.robots()) {
      if (r.index() == index) {
        return r.truePose();
      }
    }
    return ArPose.ORIGIN;
  }

  // ------------------------------------------------------------------ mouse

  private double[] world(MouseEvent e) {
    return new double[] {vp.toWorldX(e.getX()), vp.toWorldY(e.getY())};
  }

  private void pressed(MouseEvent e) {
    requestFocus();
    lastX = e.getX();
    lastY = e.getY();
    if (e.getButton() != MouseButton.PRIMARY) {
      panning = true;
      return;
    }
    start = world(e);
    current = start;
    dragHeading = Double.NaN;
    if (tool == Tool.MOVE) {
      dragRobot = robotAt(start[0], start[1]);
      dragObject = dragRobot >= 0 ? null : coloredObjectAt(e.getX(), e.getY());
      dragObstacle = dragRobot >= 0 || dragObject != null ? null : obstacleAt(e.getX(), e.getY());
      if (dragRobot < 0 && dragObject == null && dragObstacle == null) {
        panning = true;
        start = null;
      }
    }
    paint();
  }

  private void dragged(MouseEvent e) {
    if (panning) {
      vp.panPixels(e.getX() - lastX, e.getY() - lastY);
      lastX = e.getX();
      lastY = e.getY();
      paint();
      return;
    }
    if (start == null) {
      return;
    }
    current = world(e);
    if (tool == Tool.PLACE
        && Math.hypot(current[0] - start[0], current[1] - start[1]) * vp.scale() > 5) {
      dragHeading = Math.toDegrees(Math.atan2(current[1] - start[1], current[0] - start[0]));
    }
    paint();
  }

  private void released(MouseEvent e) {
    if (panning) {
      panning = false;
      return;
    }
    if (start == null) {
      return;
    }
    current = world(e);
    try {
      if (dragRobot >= 0) {
        controller.placeRobot(dragRobot, placement());
        odometryToWorld.remove(dragRobot);
        status.accept("Moved robot " + (dragRobot + 1));
      } else if (dragObject != null) {
        controller
            .world()
            .coloredObjects()
            .move(
                dragObject.id(),
                dragObject.x() + current[0] - start[0],
                dragObject.y() + current[1] - start[1]);
        status.accept("Moved the " + dragObject.name());
      } else if (dragObstacle != null) {
        controller.moveObstacle(dragObstacle, current[0] - start[0], current[1] - start[1]);
        status.accept("Moved obstacle");
      } else if (tool == Tool.PLACE) {
        controller.placeRobot(robotIndex, placement());
        odometryToWorld.remove(robotIndex);
        status.accept("Placed robot " + (robotIndex + 1));
      } else if (tool == Tool.BOX) {
        if (Math.abs(current[0] - start[0]) > 10 && Math.abs(current[1] - start[1]) > 10) {
          controller.addBox(start[0], start[1], current[0], current[1]);
          status.accept("Added a box");
        }
      }
    } catch (RuntimeException ex) {
      status.accept(ex.getMessage());
    }
    start = null;
    dragObstacle = null;
    dragObject = null;
    dragRobot = -1;
    changed.run();
    refresh();
  }

  private void scrolled(ScrollEvent e) {
    vp.zoomAt(Math.pow(1.0025, e.getDeltaY()), e.getX(), e.getY());
    paint();
    e.consume();
  }

  private int robotAt(double x, double y) {
    for (SimSnapshot.RobotView r : snapshot.robots()) {
      if (inside(r.footprint(), x, y)) {
        return r.index();
      }
    }
    return -1;
  }

  private ColoredObject coloredObjectAt(double sx, double sy) {
    double wx = vp.toWorldX(sx);
    double wy = vp.toWorldY(sy);
    double tol = 6 / vp.scale();
    for (ColoredObject o : objects) {
      double reach = Math.max(o.width(), o.depth()) / 2 + tol;
      if (Math.hypot(o.x() - wx, o.y() - wy) <= reach) {
        return o;
      }
    }
    return null;
  }

  private SimObstacle obstacleAt(double sx, double sy) {
    double wx = vp.toWorldX(sx);
    double wy = vp.toWorldY(sy);
    double tol = 8 / vp.scale();
    for (SimObstacle o : snapshot.obstacles()) {
      for (ArLineSegment s : o.segments()) {
        if (segmentDistance(s, wx, wy) <= tol) {
          return o;
        }
      }
      if (closedPolygonContains(o.segments(), wx, wy)) {
        return o;
      }
    }
    return null;
  }

  static boolean inside(List<ArPose> poly, double x, double y) {
    boolean in = false;
    for (int i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
      ArPose a = poly.get(i);
      ArPose b = poly.get(j);
      if ((a.y() > y) != (b.y() > y)
          && x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x()) {
        in = !in;
      }
    }
    return in;
  }

  private static boolean closedPolygonContains(List<ArLineSegment> segs, double x, double y) {
    boolean in = false;
    for (ArLineSegment s : segs) {
      if ((s.y1() > y) != (s.y2() > y)
          && x < (s.x2() - s.x1()) * (y - s.y1()) / (s.y2() - s.y1()) + s.x1()) {
        in = !in;
      }
    }
    return in;
  }

  static double segmentDistance(ArLineSegment s, double x, double y) {
    double dx = s.x2() - s.x1();
    double dy = s.y2() - s.y1();
    double len2 = dx * dx + dy * dy;
    double t =
        len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - s.x1()) * dx + (y - s.y1()) * dy) / len2));
    return Math.hypot(s.x1() + t * dx - x, s.y1() + t * dy - y);
  }
}
