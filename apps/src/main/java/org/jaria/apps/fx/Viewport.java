package org.jaria.apps.fx;

/**
 * The mapping between map coordinates (mm, y up) and the pixels of a view (y down): which map point
 * is at the view's centre, and how many pixels a millimetre takes. Zooming keeps the point under
 * the mouse still, as desktop map viewers do.
 *
 * <p>Plain mutable state for one view, used on the JavaFX thread.
 */
public final class Viewport {

  /** Smallest zoom: 1 pixel per 2 km. */
  public static final double MIN_SCALE = 1.0 / 2000;

  /** Largest zoom: 20 pixels per mm. */
  public static final double MAX_SCALE = 20;

  private double centerX;
  private double centerY;
  private double scale = 0.05;
  private double width = 1;
  private double height = 1;

  /** The view's size in pixels. */
  public void setSize(double w, double h) {
    width = Math.max(1, w);
    height = Math.max(1, h);
  }

  /** View width in pixels. */
  public double width() {
    return width;
  }

  /** View height in pixels. */
  public double height() {
    return height;
  }

  /** Pixels per millimetre. */
  public double scale() {
    return scale;
  }

  /** Map x at the view's centre, mm. */
  public double centerX() {
    return centerX;
  }

  /** Map y at the view's centre, mm. */
  public double centerY() {
    return centerY;
  }

  /** Puts map point (x, y) at the view's centre. */
  public void setCenter(double x, double y) {
    centerX = x;
    centerY = y;
  }

  /** Sets the zoom (clamped to {@link #MIN_SCALE}..{@link #MAX_SCALE}). */
  public void setScale(double pixelsPerMm) {
    scale = Math.max(MIN_SCALE, Math.min(MAX_SCALE, pixelsPerMm));
  }

  /** View x of map x. */
  public double toScreenX(double x) {
    return width / 2 + (x - centerX) * scale;
  }

  /** View y of map y (the view's y grows downwards). */
  public double toScreenY(double y) {
    return height / 2 - (y - centerY) * scale;
  }

  /** Map x of view x. */
  public double toWorldX(double sx) {
    return centerX + (sx - width / 2) / scale;
  }

  /** Map y of view y. */
  public double toWorldY(double sy) {
    return centerY - (sy - height / 2) / scale;
  }

  /** Map x at the view's left edge. */
  public double minVisibleX() {
    return toWorldX(0);
  }

  /** Map x at the view's right edge. */
  public double maxVisibleX() {
    return toWorldX(width);
  }

  /** Map y at the view's bottom edge. */
  public double minVisibleY() {
    return toWorldY(height);
  }

  /** Map y at the view's top edge. */
  public double maxVisibleY() {
    return toWorldY(0);
  }

  /** Moves the view by a drag of (dx, dy) pixels: the map follows the mouse. */
  public void panPixels(double dx, double dy) {
    centerX -= dx / scale;
    centerY += dy / scale;
  }

  /** Multiplies the zoom by {@code factor}, keeping the map point under view point (sx, sy). */
  public void zoomAt(double factor, double sx, double sy) {
    double wx = toWorldX(sx);
    double wy = toWorldY(sy);
    setScale(scale * factor);
    centerX = wx - (sx - width / 2) / scale;
    centerY = wy + (sy - height / 2) / scale;
  }

  /**
   * Zooms and centres so the box (minX, minY)-(maxX, maxY) fills the view, with {@code
   * marginPixels} to spare on every side.
   */
  public void fit(double minX, double minY, double maxX, double maxY, double marginPixels) {
    double w = Math.max(1, maxX - minX);
    double h = Math.max(1, maxY - minY);
    double sx = Math.max(1, width - 2 * marginPixels) / w;
    double sy = Math.max(1, height - 2 * marginPixels) / h;
    setScale(Math.min(sx, sy));
    setCenter((minX + maxX) / 2, (minY + maxY) / 2);
  }

  /** Whether the map box (x0, y0)-(x1, y1) (any corner order) overlaps the view. */
  public boolean intersects(double x0, double y0, double x1, double y1) {
    return Math.max(x0, x1) >= minVisibleX()
        && Math.min(x0, x1) <= maxVisibleX()
        && Math.max(y0, y1) >= minVisibleY()
        && Math.min(y0, y1) <= maxVisibleY();
  }
}
