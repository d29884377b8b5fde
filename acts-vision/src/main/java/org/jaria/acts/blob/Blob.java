package org.jaria.acts.blob;

/**
 * One tracked blob's statistics, in image pixel coordinates (column x from the left, row y from the
 * top), as ACTS reports them.
 *
 * @param area number of pixels
 * @param xcg centre of gravity column, rounded to the nearest pixel
 * @param ycg centre of gravity row, rounded
 * @param left leftmost column
 * @param right rightmost column
 * @param top topmost row
 * @param bottom bottom row
 * @param xCentroid exact centre of gravity column
 * @param yCentroid exact centre of gravity row
 */
public record Blob(
    int area,
    int xcg,
    int ycg,
    int left,
    int right,
    int top,
    int bottom,
    double xCentroid,
    double yCentroid) {

  /** Bounding box width in pixels. */
  public int width() {
    return right - left + 1;
  }

  /** Bounding box height in pixels. */
  public int height() {
    return bottom - top + 1;
  }
}
