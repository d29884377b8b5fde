package org.jaria.apps.fx;

import java.util.Arrays;
import java.util.BitSet;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;

/**
 * Draws a map's sensor points (tens of thousands) fast enough to pan and zoom smoothly.
 *
 * <p>The points are bucketed once into a grid of square cells, so a zoomed-in view visits only the
 * cells it shows (culling). Each visible point sets pixels of an int buffer the size of the view,
 * which becomes one image; no per-point drawing calls and no allocation while drawing. When zoomed
 * out, many points fall on the same pixel and each costs one array write (the level of detail is
 * the pixel grid itself); zoomed in, points grow to squares of their real size.
 *
 * <p>A view redrawn with nothing changed for the points (the robot moves, the map stays) gets the
 * same image back untouched: no pixel is drawn, converted or uploaded again.
 *
 * <p>Not thread-safe; build it anywhere, draw on the JavaFX thread.
 */
public final class PointLayer {

  private static final int TARGET_PER_CELL = 64;

  private final int[] xs;
  private final int[] ys;
  private final int n;
  private final int minX;
  private final int minY;
  private final int cellSize;
  private final int cols;
  private final int rows;
  private final int[] cellStart;
  private final int[] order;

  private int[] buffer = new int[0];
  private WritableImage image;

  /** What {@link #image} shows (null until drawn). */
  private Drawn drawn;

  /** A view, its colours and its selection: what one image of the points shows. */
  private record Drawn(
      int w,
      int h,
      double scale,
      double centerX,
      double centerY,
      int argb,
      int selectedArgb,
      int dot,
      BitSet selected) {

    /** A copy to keep: callers change their selection in place between frames. */
    Drawn withCopiedSelection() {
      BitSet copy = selected == null ? null : (BitSet) selected.clone();
      return new Drawn(w, h, scale, centerX, centerY, argb, selectedArgb, dot, copy);
    }
  }

  /** Indexes the points {@code (xs[i], ys[i])}, mm; the arrays are not copied or changed. */
  public PointLayer(int[] xs, int[] ys) {
    this.xs = xs;
    this.ys = ys;
    this.n = Math.min(xs.length, ys.length);
    int x0 = Integer.MAX_VALUE;
    int y0 = Integer.MAX_VALUE;
    int x1 = Integer.MIN_VALUE;
    int y1 = Integer.MIN_VALUE;
    for (int i = 0; i < n; i++) {
      x0 = Math.min(x0, xs[i]);
      y0 = Math.min(y0, ys[i]);
      x1 = Math.max(x1, xs[i]);
      y1 = Math.max(y1, ys[i]);
    }
    if (n == 0) {
      x0 = y0 = x1 = y1 = 0;
    }
    minX = x0;
    minY = y0;
    long area = Math.max(1L, (long) (x1 - x0 + 1) * (y1 - y0 + 1));
    int size = (int) Math.max(100, Math.sqrt((double) area * TARGET_PER_CELL / Math.max(1, n)));
    cellSize = size;
    cols = (x1 - x0) / size + 1;
    rows = (y1 - y0) / size + 1;
    cellStart = new int[cols * rows + 1];
    order = new int[n];
    for (int i = 0; i < n; i++) {
      cellStart[cell(xs[i], ys[i]) + 1]++;
    }
    for (int c = 0; c < cols * rows; c++) {
      cellStart[c + 1] += cellStart[c];
    }
    int[] fill = Arrays.copyOf(cellStart, cellStart.length);
    for (int i = 0; i < n; i++) {
      order[fill[cell(xs[i], ys[i])]++] = i;
    }
  }

  private int cell(int x, int y) {
    return ((y - minY) / cellSize) * cols + (x - minX) / cellSize;
  }

  /** Number of points. */
  public int size() {
    return n;
  }

  /**
   * Draws the visible points into an image of the viewport's size (reused between calls, and
   * returned as it is when the view, the colours and the selection are those it was drawn for).
   *
   * @param vp the view
   * @param argb colour of points
   * @param selected points drawn in {@code selectedArgb} (null for none)
   * @param selectedArgb colour of selected points
   * @param pointSizeMm a point's real size (the map resolution), used when zoomed in
   * @return the image, transparent where there is no point
   */
  public WritableImage render(
      Viewport vp, int argb, BitSet selected, int selectedArgb, double pointSizeMm) {
    int w = (int) Math.ceil(vp.width());
    int h = (int) Math.ceil(vp.height());
    int dot = (int) Math.max(1, Math.min(12, Math.round(pointSizeMm * vp.scale())));
    Drawn wanted =
        new Drawn(w, h, vp.scale(), vp.centerX(), vp.centerY(), argb, selectedArgb, dot, selected);
    if (wanted.equals(drawn)) { // drawn is set only with an image
      return image;
    }
    drawn = wanted.withCopiedSelection();
    if (image == null || (int) image.getWidth() != w || (int) image.getHeight() != h) {
      image = new WritableImage(w, h);
      buffer = new int[w * h];
    } else {
      Arrays.fill(buffer, 0);
    }
    int half = dot / 2;
    double s = vp.scale();
    double ox = vp.width() / 2 - vp.centerX() * s;
    double oy = vp.height() / 2 + vp.centerY() * s;
    int c0 = clamp((int) Math.floor((vp.minVisibleX() - minX) / cellSize) - 1, cols);
    int c1 = clamp((int) Math.floor((vp.maxVisibleX() - minX) / cellSize) + 1, cols);
    int r0 = clamp((int) Math.floor((vp.minVisibleY() - minY) / cellSize) - 1, rows);
    int r1 = clamp((int) Math.floor((vp.maxVisibleY() - minY) / cellSize) + 1, rows);
    for (int r = r0; r <= r1 && n > 0; r++) {
      // Cells of one row are contiguous in the index: one run per row.
      int from = cellStart[r * cols + c0];
      int to = cellStart[r * cols + c1 + 1];
      for (int k = from; k < to; k++) {
        int i = order[k];
        int px = (int) (xs[i] * s + ox) - half;
        int py = (int) (oy - ys[i] * s) - half;
        int color = selected != null && selected.get(i) ? selectedArgb : argb;
        if (dot == 1) {
          if (px >= 0 && py >= 0 && px < w && py < h) {
            buffer[py * w + px] = color;
          }
        } else {
          fillSquare(px, py, dot, w, h, color);
        }
      }
    }
    image.getPixelWriter().setPixels(0, 0, w, h, PixelFormat.getIntArgbPreInstance(), buffer, 0, w);
    return image;
  }

  private void fillSquare(int px, int py, int dot, int w, int h, int color) {
    int xa = Math.max(0, px);
    int xb = Math.min(w, px + dot);
    int ya = Math.max(0, py);
    int yb = Math.min(h, py + dot);
    if (xa >= xb) {
      return;
    }
    for (int y = ya; y < yb; y++) {
      Arrays.fill(buffer, y * w + xa, y * w + xb, color);
    }
  }

  private static int clamp(int v, int count) {
    return Math.max(0, Math.min(count - 1, v));
  }

  /**
   * Indices of the points inside the map box (x0, y0)-(x1, y1) (any corner order), set in {@code
   * out}.
   */
  public void select(double x0, double y0, double x1, double y1, BitSet out) {
    double ax = Math.min(x0, x1);
    double bx = Math.max(x0, x1);
    double ay = Math.min(y0, y1);
    double by = Math.max(y0, y1);
    if (n == 0) {
      return;
    }
    int c0 = clamp((int) Math.floor((ax - minX) / cellSize), cols);
    int c1 = clamp((int) Math.floor((bx - minX) / cellSize), cols);
    int r0 = clamp((int) Math.floor((ay - minY) / cellSize), rows);
    int r1 = clamp((int) Math.floor((by - minY) / cellSize), rows);
    for (int r = r0; r <= r1; r++) {
      for (int k = cellStart[r * cols + c0]; k < cellStart[r * cols + c1 + 1]; k++) {
        int i = order[k];
        if (xs[i] >= ax && xs[i] <= bx && ys[i] >= ay && ys[i] <= by) {
          out.set(i);
        }
      }
    }
  }

  /** The index of the point nearest (x, y) within {@code radius} mm, or -1. */
  public int nearest(double x, double y, double radius) {
    BitSet near = new BitSet();
    select(x - radius, y - radius, x + radius, y + radius, near);
    int best = -1;
    double bestD = radius * radius;
    for (int i = near.nextSetBit(0); i >= 0; i = near.nextSetBit(i + 1)) {
      double dx = xs[i] - x;
      double dy = ys[i] - y;
      double d = dx * dx + dy * dy;
      if (d <= bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  }
}
