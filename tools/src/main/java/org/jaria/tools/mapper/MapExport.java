package org.jaria.tools.mapper;

import javafx.scene.SnapshotParameters;
import javafx.scene.canvas.Canvas;
import javafx.scene.image.WritableImage;
import org.jaria.tools.fx.PointLayer;
import org.jaria.tools.fx.Viewport;

/** Renders a whole map into an image (File → Export PNG). JavaFX thread. */
public final class MapExport {

  /** Margin around the map, pixels. */
  static final int MARGIN = 20;

  private MapExport() {}

  /**
   * The map drawn at 20 mm per pixel (a typical map resolution), or smaller so that no side exceeds
   * {@code maxSide} pixels.
   */
  public static WritableImage render(MapContent content, RenderOptions options, int maxSide) {
    double[] b = content.bounds();
    double w = b[2] - b[0];
    double h = b[3] - b[1];
    double scale = 1.0 / 20;
    double longest = Math.max(w, h) * scale + 2 * MARGIN;
    if (longest > maxSide) {
      scale *= (maxSide - 2 * MARGIN) / (Math.max(w, h) * scale);
    }
    int pw = (int) Math.ceil(w * scale) + 2 * MARGIN;
    int ph = (int) Math.ceil(h * scale) + 2 * MARGIN;
    Viewport vp = new Viewport();
    vp.setSize(pw, ph);
    vp.setScale(scale);
    vp.setCenter((b[0] + b[2]) / 2, (b[1] + b[3]) / 2);
    Canvas canvas = new Canvas(pw, ph);
    int[] xs = content.points().xArray();
    int[] ys = content.points().yArray();
    new MapRenderer()
        .render(canvas.getGraphicsContext2D(), vp, content, new PointLayer(xs, ys), null, options);
    return canvas.snapshot(new SnapshotParameters(), null);
  }
}
