package org.jaria.apps.eztrain;

import java.util.ArrayList;
import java.util.List;
import javafx.scene.Cursor;
import javafx.scene.canvas.Canvas;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.image.ImageView;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import javafx.scene.input.MouseButton;
import javafx.scene.input.MouseEvent;
import javafx.scene.layout.Pane;
import javafx.scene.paint.Color;

/**
 * The training window's image: the frame in the current view mode, magnified 1×–6× without
 * smoothing so every pixel stays visible, with the tools' rectangle and brush drawn over it. The
 * primary button trains with the selected tool, the right button cycles the view modes and the
 * middle button grabs a frame (as in ACTS).
 */
final class TrainingPane extends Pane {

  /** What the pane asks its owner to do. */
  interface Listener {
    /** Add or Remove over the rectangle (image pixels, inclusive). */
    void rect(TrainTool tool, int x0, int y0, int x1, int y1);

    /** Draw or Erase along a stroke (image pixels). */
    void stroke(TrainTool tool, List<int[]> points);

    /** Pick a pixel. */
    void pick(int x, int y);

    /** Right click: next view mode. */
    void cycleView();

    /** Middle click: grab a frame. */
    void grabFrame();
  }

  private final ImageView image = new ImageView();
  private final Canvas overlay = new Canvas();
  private final Listener listener;
  private WritableImage buffer;
  private int imageW = 1;
  private int imageH = 1;
  private int magnification = 3;
  private TrainTool tool = TrainTool.ADD;
  private Color drawColor = Color.RED;
  private int brush = 1;
  private int[] start;
  private int[] current;
  private final List<int[]> stroke = new ArrayList<>();

  TrainingPane(Listener listener) {
    this.listener = listener;
    image.setSmooth(false);
    image.setPreserveRatio(false);
    overlay.setMouseTransparent(true);
    getChildren().addAll(image, overlay);
    setCursor(Cursor.CROSSHAIR);
    addEventHandler(MouseEvent.MOUSE_PRESSED, this::pressed);
    addEventHandler(MouseEvent.MOUSE_DRAGGED, this::dragged);
    addEventHandler(MouseEvent.MOUSE_RELEASED, this::released);
    addEventHandler(MouseEvent.MOUSE_MOVED, this::hover);
    addEventHandler(MouseEvent.MOUSE_EXITED, e -> drawOverlay());
    setStyle("-fx-background-color: #202020;");
  }

  /** Shows new pixels (ARGB, {@code w × h}). */
  void setPixels(int[] argb, int w, int h) {
    if (buffer == null || imageW != w || imageH != h) {
      buffer = new WritableImage(w, h);
      imageW = w;
      imageH = h;
      image.setImage(buffer);
      resize();
    }
    buffer.getPixelWriter().setPixels(0, 0, w, h, PixelFormat.getIntArgbInstance(), argb, 0, w);
  }

  /** Magnification 1..6. */
  void setMagnification(int m) {
    magnification = Math.max(1, Math.min(6, m));
    resize();
  }

  void setTool(TrainTool t) {
    tool = t;
    cancel();
  }

  void setDrawColor(Color c) {
    drawColor = c;
    drawOverlay();
  }

  void setBrush(int size) {
    brush = size;
  }

  /** The colour of the tools' rectangle and brush. */
  Color drawColor() {
    return drawColor;
  }

  /** The Draw/Erase brush size shown. */
  int brush() {
    return brush;
  }

  /** The magnification, 1..6. */
  int magnification() {
    return magnification;
  }

  /** Abandons a drag in progress. */
  void cancel() {
    start = null;
    stroke.clear();
    drawOverlay();
  }

  /** Whether a drag is in progress. */
  boolean dragging() {
    return start != null;
  }

  private void resize() {
    double w = imageW * magnification;
    double h = imageH * magnification;
    image.setFitWidth(w);
    image.setFitHeight(h);
    overlay.setWidth(w);
    overlay.setHeight(h);
    setPrefSize(w, h);
    setMinSize(w, h);
    setMaxSize(w, h);
    drawOverlay();
  }

  /** Image pixel under the mouse (may be outside the image). */
  private int[] pixel(MouseEvent e) {
    return new int[] {
      (int) Math.floor(e.getX() / magnification), (int) Math.floor(e.getY() / magnification)
    };
  }

  private void pressed(MouseEvent e) {
    if (e.getButton() == MouseButton.SECONDARY) {
      cancel();
      listener.cycleView();
      return;
    }
    if (e.getButton() == MouseButton.MIDDLE) {
      listener.grabFrame();
      return;
    }
    if (e.getButton() != MouseButton.PRIMARY) {
      return;
    }
    int[] p = pixel(e);
    if (tool == TrainTool.PICK) {
      listener.pick(p[0], p[1]);
      return;
    }
    start = p;
    current = p;
    stroke.clear();
    stroke.add(p);
    drawOverlay();
  }

  private void dragged(MouseEvent e) {
    if (start == null) {
      return;
    }
    int[] p = pixel(e);
    current = p;
    if (tool == TrainTool.DRAW || tool == TrainTool.ERASE) {
      int[] last = stroke.get(stroke.size() - 1);
      if (last[0] != p[0] || last[1] != p[1]) {
        stroke.add(p);
      }
    }
    drawOverlay();
  }

  private void released(MouseEvent e) {
    if (start == null || e.getButton() != MouseButton.PRIMARY) {
      return;
    }
    int[] a = start;
    int[] b = pixel(e);
    start = null;
    switch (tool) {
      case ADD, REMOVE -> listener.rect(tool, a[0], a[1], b[0], b[1]);
      case DRAW, ERASE -> listener.stroke(tool, List.copyOf(stroke));
      case PICK -> {}
    }
    stroke.clear();
    drawOverlay();
  }

  private void hover(MouseEvent e) {
    current = pixel(e);
    drawOverlay();
  }

  private void drawOverlay() {
    GraphicsContext g = overlay.getGraphicsContext2D();
    g.clearRect(0, 0, overlay.getWidth(), overlay.getHeight());
    g.setStroke(drawColor);
    g.setLineWidth(1);
    int m = magnification;
    if (start != null && (tool == TrainTool.ADD || tool == TrainTool.REMOVE)) {
      int x0 = Math.min(start[0], current[0]);
      int y0 = Math.min(start[1], current[1]);
      int x1 = Math.max(start[0], current[0]);
      int y1 = Math.max(start[1], current[1]);
      g.strokeRect(x0 * m + 0.5, y0 * m + 0.5, (x1 - x0 + 1) * m - 1, (y1 - y0 + 1) * m - 1);
    } else if ((tool == TrainTool.DRAW || tool == TrainTool.ERASE)
        && current != null
        && isHover()) {
      int lo = (brush - 1) / 2;
      g.strokeRect(
          (current[0] - lo) * m + 0.5, (current[1] - lo) * m + 0.5, brush * m - 1, brush * m - 1);
      for (int[] p : stroke) {
        g.strokeRect((p[0] - lo) * m + 0.5, (p[1] - lo) * m + 0.5, brush * m - 1, brush * m - 1);
      }
    }
  }
}
