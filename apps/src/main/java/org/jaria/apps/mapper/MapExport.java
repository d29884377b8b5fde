package org.jaria.apps.mapper;

import java.util.function.DoubleConsumer;
import javafx.scene.SnapshotParameters;
import javafx.scene.canvas.Canvas;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import org.jaria.acts.image.RgbImage;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.fx.Viewport;

/**
 * Renders a whole map into an image (File → Export PNG), in tiles: each tile is drawn on the JavaFX
 * thread as one short task, so the window keeps answering between tiles while a big export runs.
 */
public final class MapExport {

  /** Margin around the map, pixels. */
  static final int MARGIN = 20;

  /** Side of a tile, pixels. */
  static final int TILE = 512;

  private MapExport() {}

  /**
   * The map drawn at 20 mm per pixel (a typical map resolution), or smaller so that no side exceeds
   * {@code maxSide} pixels. Call from a worker thread, never the JavaFX thread: the tiles are drawn
   * there one by one.
   *
   * @param progress told the fraction done (0..1) after each tile, on the calling thread
   */
  public static RgbImage render(
      MapContent content, RenderOptions options, int maxSide, DoubleConsumer progress) {
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
    Viewport whole = new Viewport();
    whole.setSize(pw, ph);
    whole.setScale(scale);
    whole.setCenter((b[0] + b[2]) / 2, (b[1] + b[3]) / 2);
    PointLayer points = new PointLayer(content.points().xArray(), content.points().yArray());
    int[] out = new int[pw * ph];
    int cols = (pw + TILE - 1) / TILE;
    int rows = (ph + TILE - 1) / TILE;
    for (int r = 0; r < rows; r++) {
      for (int c = 0; c < cols; c++) {
        int x0 = c * TILE;
        int y0 = r * TILE;
        int tw = Math.min(TILE, pw - x0);
        int th = Math.min(TILE, ph - y0);
        // The scale bar goes once, in the image's bottom-left corner.
        boolean bar = c == 0 && r == rows - 1;
        FxRuntime.run(
            () -> drawTile(content, options, points, whole, x0, y0, tw, th, bar, out, pw), 120);
        progress.accept((double) (r * cols + c + 1) / (rows * cols));
      }
    }
    for (int i = 0; i < out.length; i++) {
      out[i] &= 0xFFFFFF;
    }
    return new RgbImage(pw, ph, out);
  }

  private static void drawTile(
      MapContent content,
      RenderOptions options,
      PointLayer points,
      Viewport whole,
      int x0,
      int y0,
      int tw,
      int th,
      boolean scaleBar,
      int[] out,
      int stride) {
    Viewport vp = new Viewport();
    vp.setSize(tw, th);
    vp.setScale(whole.scale());
    vp.setCenter(whole.toWorldX(x0 + tw / 2.0), whole.toWorldY(y0 + th / 2.0));
    Canvas canvas = new Canvas(tw, th);
    MapRenderer r = new MapRenderer();
    r.setScaleBar(scaleBar);
    r.render(canvas.getGraphicsContext2D(), vp, content, points, null, options);
    WritableImage img = canvas.snapshot(new SnapshotParameters(), null);
    img.getPixelReader()
        .getPixels(0, 0, tw, th, PixelFormat.getIntArgbInstance(), out, y0 * stride + x0, stride);
  }
}
