package org.jaria.arnl.grid;

/**
 * Where a square-celled grid lies on the map: the corner of cell (0, 0), the cell size and the
 * number of cells. Cell (i, j) covers x in [originX + i·res, originX + (i+1)·res) and likewise in
 * y; cells are stored row by row, index {@code j * width + i}. Immutable.
 *
 * @param originX x of the grid's lower-left corner, mm
 * @param originY y of the grid's lower-left corner, mm
 * @param res cell size, mm
 * @param width cells along x
 * @param height cells along y
 */
public record GridSpec(double originX, double originY, double res, int width, int height) {

  /** Most cells a grid may have (4096 × 4096). */
  public static final long MAX_CELLS = 4096L * 4096L;

  /** Checks the values. */
  public GridSpec {
    if (!(res > 0) || !Double.isFinite(res)) {
      throw new IllegalArgumentException("grid resolution must be a positive number, got " + res);
    }
    if (width < 1 || height < 1 || (long) width * height > MAX_CELLS) {
      throw new IllegalArgumentException(
          "grid of "
              + width
              + " x "
              + height
              + " cells is empty or too large (at most "
              + MAX_CELLS
              + " cells): use a coarser resolution");
    }
  }

  /**
   * The grid covering the rectangle (minX, minY)–(maxX, maxY) plus {@code margin} on every side.
   */
  public static GridSpec covering(
      double minX, double minY, double maxX, double maxY, double margin, double res) {
    double x0 = Math.floor((minX - margin) / res) * res;
    double y0 = Math.floor((minY - margin) / res) * res;
    int w = (int) Math.ceil((maxX + margin - x0) / res) + 1;
    int h = (int) Math.ceil((maxY + margin - y0) / res) + 1;
    return new GridSpec(x0, y0, res, w, h);
  }

  /** Number of cells. */
  public int size() {
    return width * height;
  }

  /** Column of the cell holding x (may be outside 0..width-1). */
  public int cellX(double x) {
    return (int) Math.floor((x - originX) / res);
  }

  /** Row of the cell holding y (may be outside 0..height-1). */
  public int cellY(double y) {
    return (int) Math.floor((y - originY) / res);
  }

  /** Whether cell (i, j) exists. */
  public boolean inside(int i, int j) {
    return i >= 0 && j >= 0 && i < width && j < height;
  }

  /** Index of the cell holding (x, y), or −1 outside the grid. */
  public int indexOf(double x, double y) {
    int i = cellX(x);
    int j = cellY(y);
    return inside(i, j) ? j * width + i : -1;
  }

  /** x of the centre of column i. */
  public double centerX(int i) {
    return originX + (i + 0.5) * res;
  }

  /** y of the centre of row j. */
  public double centerY(int j) {
    return originY + (j + 0.5) * res;
  }

  /** Largest x covered. */
  public double maxX() {
    return originX + width * res;
  }

  /** Largest y covered. */
  public double maxY() {
    return originY + height * res;
  }
}
