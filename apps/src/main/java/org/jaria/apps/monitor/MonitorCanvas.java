package org.jaria.apps.monitor;

import java.util.function.BiConsumer;
import java.util.function.Consumer;
import javafx.scene.canvas.Canvas;
import javafx.scene.input.MouseButton;
import javafx.scene.input.MouseEvent;
import javafx.scene.input.ScrollEvent;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.net.data.RobotUpdate;

/**
 * The monitor's map view: draws the {@link MonitorState} and turns the mouse into commands. With
 * the {@link Tool#MOVE} tool, dragging the robot relocalizes it where it is dropped (heading kept)
 * and dragging elsewhere pans; with {@link Tool#GOTO}, a click on a goal's marker sends the robot
 * to that goal, a click elsewhere to that point, and a drag to that point facing the drag's
 * direction. The wheel zooms.
 */
final class MonitorCanvas extends Canvas {

  /** What a press on the map does. */
  enum Tool {
    /** Pan, or drag the robot to relocalize it. */
    MOVE,
    /** Send the robot to the point clicked. */
    GOTO
  }

  /** A click this close to a goal's marker (pixels) means that goal. */
  private static final double GOAL_PIXELS = 8;

  /** Pixels a drag must cover before it counts as one. */
  private static final double DRAG_PIXELS = 6;

  private final Viewport vp = new Viewport();
  private final MonitorRenderer renderer = new MonitorRenderer();
  private final MonitorState state;
  private MonitorRenderer.Layers layers = new MonitorRenderer.Layers(true, true, true);
  private Tool tool = Tool.MOVE;
  private BiConsumer<ArPose, Boolean> onGoto = (p, h) -> {};
  private Consumer<ArPose> onLocalize = p -> {};
  private Consumer<String> onGotoGoal = g -> {};
  private boolean fitted;
  private long fittedVersion = -1;
  private ArPose drawnRobot;
  // Mouse state (JavaFX thread).
  private double pressX;
  private double pressY;
  private double lastX;
  private double lastY;
  private boolean draggingRobot;
  private boolean dragged;
  private ArPose ghost;

  MonitorCanvas(MonitorState state) {
    super(800, 600);
    this.state = state;
    setFocusTraversable(true);
    addEventHandler(MouseEvent.MOUSE_PRESSED, this::pressed);
    addEventHandler(MouseEvent.MOUSE_DRAGGED, this::draggedTo);
    addEventHandler(MouseEvent.MOUSE_RELEASED, this::released);
    addEventHandler(ScrollEvent.SCROLL, this::scrolled);
  }

  @Override
  public boolean isResizable() {
    return true;
  }

  @Override
  public double prefWidth(double height) {
    return 800;
  }

  @Override
  public double prefHeight(double width) {
    return 600;
  }

  @Override
  public double minWidth(double height) {
    return 100;
  }

  @Override
  public double minHeight(double width) {
    return 100;
  }

  @Override
  public double maxWidth(double height) {
    return Double.MAX_VALUE;
  }

  @Override
  public double maxHeight(double width) {
    return Double.MAX_VALUE;
  }

  @Override
  public void resize(double w, double h) {
    setWidth(w);
    setHeight(h);
    redraw();
  }

  void setTool(Tool t) {
    tool = t;
  }

  Tool tool() {
    return tool;
  }

  void setLayers(MonitorRenderer.Layers l) {
    layers = l;
    redraw();
  }

  /** Called with a goal pose and whether its heading matters. */
  void setOnGoto(BiConsumer<ArPose, Boolean> h) {
    onGoto = h;
  }

  /** Called with the name of a map goal clicked with the goto tool. */
  void setOnGotoGoal(Consumer<String> h) {
    onGotoGoal = h;
  }

  /** Called with the pose the robot was dropped at. */
  void setOnLocalize(Consumer<ArPose> h) {
    onLocalize = h;
  }

  Viewport viewport() {
    return vp;
  }

  /** The robot's pose as last drawn (null before the first update). */
  ArPose drawnRobot() {
    return drawnRobot;
  }

  /** Zooms to show the whole map. */
  void fit() {
    MonitorState.MapView m = state.map;
    vp.setSize(getWidth(), getHeight());
    if (m != null) {
      ArMap map = m.map();
      vp.fit(
          map.getMinPos().x(), map.getMinPos().y(), map.getMaxPos().x(), map.getMaxPos().y(), 20);
      fitted = true;
      fittedVersion = m.version();
    }
    redraw();
  }

  /** Draws the current state (JavaFX thread). */
  void redraw() {
    vp.setSize(getWidth(), getHeight());
    MonitorState.MapView m = state.map;
    if (m != null && (!fitted || m.version() != fittedVersion)) {
      fit();
      return;
    }
    RobotUpdate u = state.robot;
    drawnRobot = u == null ? null : u.getPose();
    renderer.render(getGraphicsContext2D(), vp, state, layers, ghost);
  }

  private ArPose at(double sx, double sy) {
    return new ArPose(vp.toWorldX(sx), vp.toWorldY(sy));
  }

  private boolean onRobot(double sx, double sy) {
    RobotUpdate u = state.robot;
    if (u == null) {
      return false;
    }
    double r = state.physical != null ? state.physical.radius() : 250;
    double dx = vp.toScreenX(u.x()) - sx;
    double dy = vp.toScreenY(u.y()) - sy;
    return Math.hypot(dx, dy) <= Math.max(8, r * vp.scale());
  }

  private void pressed(MouseEvent e) {
    requestFocus();
    pressX = lastX = e.getX();
    pressY = lastY = e.getY();
    dragged = false;
    draggingRobot =
        e.getButton() == MouseButton.PRIMARY && tool == Tool.MOVE && onRobot(pressX, pressY);
  }

  private void draggedTo(MouseEvent e) {
    if (Math.hypot(e.getX() - pressX, e.getY() - pressY) >= DRAG_PIXELS) {
      dragged = true;
    }
    RobotUpdate u = state.robot;
    if (draggingRobot && u != null) {
      ArPose p = at(e.getX(), e.getY());
      ghost = new ArPose(p.x(), p.y(), u.th());
    } else if (tool == Tool.GOTO && dragged) {
      ArPose p = at(pressX, pressY);
      ghost = new ArPose(p.x(), p.y(), heading(e.getX(), e.getY()));
    } else if (tool == Tool.MOVE || e.getButton() != MouseButton.PRIMARY) {
      vp.panPixels(e.getX() - lastX, e.getY() - lastY);
    }
    lastX = e.getX();
    lastY = e.getY();
    redraw();
  }

  private double heading(double sx, double sy) {
    return Math.toDegrees(Math.atan2(-(sy - pressY), sx - pressX));
  }

  private void released(MouseEvent e) {
    ArPose g = ghost;
    ghost = null;
    if (draggingRobot) {
      draggingRobot = false;
      if (dragged && g != null) {
        onLocalize.accept(g);
      }
    } else if (tool == Tool.GOTO && e.getButton() == MouseButton.PRIMARY) {
      ArPose p = at(pressX, pressY);
      String goal = dragged ? null : goalAt(pressX, pressY);
      if (goal != null) {
        onGotoGoal.accept(goal);
      } else if (dragged) {
        onGoto.accept(new ArPose(p.x(), p.y(), heading(e.getX(), e.getY())), true);
      } else {
        onGoto.accept(p, false);
      }
    }
    redraw();
  }

  /** The name of the map goal drawn under view point (sx, sy), or null. */
  private String goalAt(double sx, double sy) {
    MonitorState.MapView m = state.map;
    if (m == null) {
      return null;
    }
    for (ArMapObject o : m.map().getGoals()) {
      double dx = vp.toScreenX(o.pose().x()) - sx;
      double dy = vp.toScreenY(o.pose().y()) - sy;
      if (!o.name().isEmpty() && Math.hypot(dx, dy) <= GOAL_PIXELS) {
        return o.name();
      }
    }
    return null;
  }

  private void scrolled(ScrollEvent e) {
    vp.zoomAt(e.getDeltaY() > 0 ? 1.25 : 1 / 1.25, e.getX(), e.getY());
    redraw();
  }

  /** Zooms by {@code factor} about the view's centre. */
  void zoom(double factor) {
    vp.zoomAt(factor, getWidth() / 2, getHeight() / 2);
    redraw();
  }
}
