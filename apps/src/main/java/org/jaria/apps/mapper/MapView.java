package org.jaria.apps.mapper;

import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.LongConsumer;
import javafx.application.Platform;
import javafx.scene.canvas.Canvas;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import javafx.scene.input.MouseButton;
import javafx.scene.input.MouseEvent;
import javafx.scene.input.ScrollEvent;
import javafx.scene.input.ZoomEvent;
import javafx.scene.layout.Region;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Viewport;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapPoints;

/**
 * The map editor's drawing area: shows a {@link MapDocument} through a {@link Viewport}, zooms with
 * the wheel (about the mouse), pans with the middle or right button, Space-drag or the arrow keys,
 * and passes primary-button drags to the active {@link MapTool}.
 *
 * <p>Drawing is coalesced: many changes within one pulse give one redraw.
 */
public final class MapView extends Region implements ToolContext {

  private final Canvas canvas = new Canvas(10, 10);
  private final Viewport vp = new Viewport();
  private boolean fitPending;

  /** The viewport's scale and centre right after the last fit; null before the first. */
  private double[] lastFit;

  private final MapRenderer renderer = new MapRenderer();
  private final MapSelection selection;
  private MapDocument document;
  private PointLayer layer;
  private ArMapPoints layerOf;
  private RenderOptions options = RenderOptions.DEFAULT;
  private boolean snapping;
  private MapTool tool = new SelectTool();
  private Consumer<String> statusSink = s -> {};
  private Consumer<double[]> mouseSink = p -> {};
  private LongConsumer renameHandler = id -> {};
  private boolean redrawPending;
  private boolean panning;
  private boolean spaceDown;
  private boolean toolDragging;
  private double lastX;
  private double lastY;
  private long frames;

  /** A view of {@code document} with {@code selection}. */
  public MapView(MapDocument document, MapSelection selection) {
    this.document = document;
    this.selection = selection;
    getChildren().add(canvas);
    setFocusTraversable(true);
    setMinSize(100, 100);
    setPrefSize(800, 600);
    canvas.setFocusTraversable(false);
    addEventHandler(MouseEvent.MOUSE_PRESSED, this::onPressed);
    addEventHandler(MouseEvent.MOUSE_DRAGGED, this::onDragged);
    addEventHandler(MouseEvent.MOUSE_RELEASED, this::onReleased);
    addEventHandler(MouseEvent.MOUSE_MOVED, this::onMoved);
    addEventHandler(ScrollEvent.SCROLL, this::onScroll);
    addEventHandler(ZoomEvent.ZOOM, e -> zoomAt(e.getZoomFactor(), e.getX(), e.getY()));
    addEventHandler(KeyEvent.KEY_PRESSED, this::onKeyPressed);
    addEventHandler(KeyEvent.KEY_RELEASED, e -> spaceDown &= e.getCode() != KeyCode.SPACE);
    selection.addListener(this::redraw);
    setCursor(tool.cursor());
  }

  @Override
  protected void layoutChildren() {
    double w = Math.max(1, getWidth());
    double h = Math.max(1, getHeight());
    if (canvas.getWidth() != w || canvas.getHeight() != h) {
      double cx = vp.centerX();
      double cy = vp.centerY();
      // A view the user has not zoomed or panned since the map was fitted keeps fitting the
      // window as it grows (the window often reaches its final size after the map is opened).
      boolean stillFitted =
          lastFit != null && lastFit[0] == vp.scale() && lastFit[1] == cx && lastFit[2] == cy;
      canvas.setWidth(w);
      canvas.setHeight(h);
      vp.setSize(w, h);
      vp.setCenter(cx, cy);
      if (fitPending || stillFitted) {
        fit();
      }
      paint();
    }
  }

  // ------------------------------------------------------------------ state

  /** Shows another document (after New or Open) and fits it into the view. */
  public void setDocument(MapDocument doc) {
    document = doc;
    selection.clear();
    fit();
  }

  @Override
  public MapDocument document() {
    return document;
  }

  @Override
  public MapSelection selection() {
    return selection;
  }

  @Override
  public Viewport viewport() {
    return vp;
  }

  @Override
  // The index is a cache of one immutable points object: the same instance, not equal content.
  @SuppressWarnings("ReferenceEquality")
  public PointLayer points() {
    ArMapPoints p = document.content().points();
    if (layer == null || layerOf != p) {
      layer = new PointLayer(p.xArray(), p.yArray());
      layerOf = p;
    }
    return layer;
  }

  /**
   * Uses {@code layer}, an index of {@code p} made elsewhere (off the JavaFX thread while a big map
   * loads), instead of indexing {@code p} when it is first drawn.
   */
  public void usePoints(ArMapPoints p, PointLayer layer) {
    this.layer = layer;
    this.layerOf = p;
  }

  /** The active tool. */
  public MapTool tool() {
    return tool;
  }

  /** Makes {@code t} the active tool (abandoning a drag of the previous one). */
  public void setTool(MapTool t) {
    tool.cancel();
    tool = t;
    toolDragging = false;
    setCursor(t.cursor());
    status(t.name());
    redraw();
  }

  /** What is shown. */
  public RenderOptions options() {
    return options;
  }

  /** Changes what is shown. */
  public void setOptions(RenderOptions o) {
    options = o;
    redraw();
  }

  /** Turns snapping to the grid on or off. */
  public void setSnapping(boolean on) {
    snapping = on;
  }

  /** Whether snapping to the grid is on. */
  public boolean isSnapping() {
    return snapping;
  }

  /** Where status messages go. */
  public void setStatusSink(Consumer<String> sink) {
    statusSink = sink;
  }

  /** Receives the mouse position in mm as it moves. */
  public void setMouseSink(Consumer<double[]> sink) {
    mouseSink = sink;
  }

  /** What to do when the user asks to rename object {@code id}. */
  public void setRenameHandler(LongConsumer handler) {
    renameHandler = handler;
  }

  /** How many times the view has been drawn (for tests). */
  public long frames() {
    return frames;
  }

  // ------------------------------------------------------------------ ToolContext

  @Override
  public double[] snap(double x, double y) {
    if (!snapping) {
      return new double[] {x, y};
    }
    double s = options.gridSize();
    return new double[] {Math.round(x / s) * s, Math.round(y / s) * s};
  }

  @Override
  public double snapStep() {
    return snapping ? options.gridSize() : 0;
  }

  @Override
  public Hit hit(double sx, double sy) {
    double tol = 7 / vp.scale();
    double wx = vp.toWorldX(sx);
    double wy = vp.toWorldY(sy);
    List<MapObjectEntry> objects = document.content().objects();
    // Point objects first (they sit on top), then lines and outlines, then areas' insides.
    long best = -1;
    double bestD = tol;
    for (MapObjectEntry e : objects) {
      if (!e.object().hasFromTo()) {
        double d = MapGeometry.distance(e.object(), wx, wy);
        if (d <= bestD) {
          bestD = d;
          best = e.id();
        }
      }
    }
    if (best >= 0) {
      return new Hit(best, -1);
    }
    for (MapObjectEntry e : objects) {
      if (e.object().hasFromTo()) {
        double d = edgeDistance(e, wx, wy);
        if (d <= bestD) {
          bestD = d;
          best = e.id();
        }
      }
    }
    if (options.lines()) {
      for (MapLine l : document.content().lines()) {
        double d = MapGeometry.segmentDistance(l.segment(), wx, wy);
        if (d <= bestD) {
          bestD = d;
          best = l.id();
        }
      }
    }
    if (best >= 0) {
      return new Hit(best, -1);
    }
    if (options.points()) {
      int p = points().nearest(wx, wy, 4 / vp.scale());
      if (p >= 0) {
        return new Hit(-1, p);
      }
    }
    for (int i = objects.size() - 1; i >= 0; i--) {
      if (objects.get(i).object().contains(wx, wy)) {
        return new Hit(objects.get(i).id(), -1);
      }
    }
    return Hit.NONE;
  }

  private static double edgeDistance(MapObjectEntry e, double x, double y) {
    double best = Double.POSITIVE_INFINITY;
    for (ArLineSegment s : e.object().getFromToSegments()) {
      best = Math.min(best, MapGeometry.segmentDistance(s, x, y));
    }
    return best;
  }

  @Override
  public void redraw() {
    if (!redrawPending) {
      redrawPending = true;
      Platform.runLater(this::paint);
    }
  }

  @Override
  public void status(String text) {
    statusSink.accept(text);
  }

  @Override
  public void rename(long id) {
    renameHandler.accept(id);
  }

  // ------------------------------------------------------------------ view commands

  /** Zooms so the whole map fits. */
  public void fit() {
    if (getWidth() < 2 || getHeight() < 2) {
      fitPending = true; // not laid out yet: fit once the view has its size
      return;
    }
    fitPending = false;
    double[] b = document.content().bounds();
    vp.fit(b[0], b[1], b[2], b[3], 24);
    lastFit = new double[] {vp.scale(), vp.centerX(), vp.centerY()};
    redraw();
  }

  /** Multiplies the zoom by {@code factor} about view point (sx, sy). */
  public void zoomAt(double factor, double sx, double sy) {
    vp.zoomAt(factor, sx, sy);
    redraw();
  }

  /** Zooms by {@code factor} about the view's centre. */
  public void zoom(double factor) {
    zoomAt(factor, vp.width() / 2, vp.height() / 2);
  }

  /** Centres the view on map point (x, y). */
  public void centerOn(double x, double y) {
    vp.setCenter(x, y);
    redraw();
  }

  /** Draws now (normally drawing waits for the next pulse). */
  public void paint() {
    redrawPending = false;
    GraphicsContext gc = canvas.getGraphicsContext2D();
    renderer.render(gc, vp, document.content(), points(), selection, options);
    tool.drawOverlay(this, gc, renderer);
    frames++;
  }

  // ------------------------------------------------------------------ input

  private boolean isPanGesture(MouseEvent e) {
    return e.getButton() == MouseButton.MIDDLE
        || e.getButton() == MouseButton.SECONDARY
        || (e.getButton() == MouseButton.PRIMARY && spaceDown);
  }

  private void onPressed(MouseEvent e) {
    requestFocus();
    lastX = e.getX();
    lastY = e.getY();
    if (isPanGesture(e)) {
      panning = true;
    } else if (e.getButton() == MouseButton.PRIMARY) {
      toolDragging = true;
      tool.pressed(this, e);
    }
    e.consume();
  }

  private void onDragged(MouseEvent e) {
    if (panning) {
      vp.panPixels(e.getX() - lastX, e.getY() - lastY);
      redraw();
    } else if (toolDragging) {
      tool.dragged(this, e);
    }
    lastX = e.getX();
    lastY = e.getY();
    mouse(e);
    e.consume();
  }

  private void onReleased(MouseEvent e) {
    if (panning) {
      panning = false;
    } else if (toolDragging && e.getButton() == MouseButton.PRIMARY) {
      toolDragging = false;
      tool.released(this, e);
    }
    e.consume();
  }

  private void onMoved(MouseEvent e) {
    tool.moved(this, e);
    mouse(e);
  }

  private void mouse(MouseEvent e) {
    mouseSink.accept(new double[] {vp.toWorldX(e.getX()), vp.toWorldY(e.getY())});
  }

  private void onScroll(ScrollEvent e) {
    if (e.isControlDown() || e.getTouchCount() == 0) {
      // A wheel zooms about the mouse; smooth for high-resolution wheels.
      zoomAt(Math.pow(1.0025, e.getDeltaY()), e.getX(), e.getY());
    } else {
      vp.panPixels(e.getDeltaX(), e.getDeltaY());
      redraw();
    }
    e.consume();
  }

  private void onKeyPressed(KeyEvent e) {
    double step = 60;
    switch (e.getCode()) {
      case SPACE -> spaceDown = true;
      case LEFT -> vp.panPixels(step, 0);
      case RIGHT -> vp.panPixels(-step, 0);
      case UP -> vp.panPixels(0, step);
      case DOWN -> vp.panPixels(0, -step);
      case ESCAPE -> {
        tool.cancel();
        toolDragging = false;
        selection.clear();
      }
      default -> {
        return;
      }
    }
    redraw();
    e.consume();
  }

  /**
   * Draws {@code raw} faintly under the map (a scan log's readings when a map was built from it),
   * or nothing with null.
   */
  public void setUnderlay(PointLayer raw) {
    renderer.setUnderlay(raw);
    redraw();
  }

  /** "1 px = 25 mm". */
  public String zoomText() {
    return String.format(Locale.ROOT, "1 px = %s", MapRenderer.formatLength(1 / vp.scale()));
  }
}
