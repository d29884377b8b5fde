package org.jaria.apps.mapper;

/**
 * What the map view shows.
 *
 * @param grid whether to draw the grid
 * @param gridSize grid spacing (and snapping step), mm
 * @param points whether to draw the sensor points
 * @param lines whether to draw the wall lines
 * @param labels whether to write object names
 * @param pointSize a point's real size (the map resolution), mm
 */
public record RenderOptions(
    boolean grid,
    double gridSize,
    boolean points,
    boolean lines,
    boolean labels,
    double pointSize) {

  /** Everything shown, 1 m grid, 20 mm points. */
  public static final RenderOptions DEFAULT = new RenderOptions(true, 1000, true, true, true, 20);

  /** These options with the grid on or off. */
  public RenderOptions withGrid(boolean on) {
    return new RenderOptions(on, gridSize, points, lines, labels, pointSize);
  }

  /** These options with another grid spacing. */
  public RenderOptions withGridSize(double mm) {
    return new RenderOptions(grid, mm, points, lines, labels, pointSize);
  }

  /** These options with points on or off. */
  public RenderOptions withPoints(boolean on) {
    return new RenderOptions(grid, gridSize, on, lines, labels, pointSize);
  }

  /** These options with lines on or off. */
  public RenderOptions withLines(boolean on) {
    return new RenderOptions(grid, gridSize, points, on, labels, pointSize);
  }

  /** These options with labels on or off. */
  public RenderOptions withLabels(boolean on) {
    return new RenderOptions(grid, gridSize, points, lines, on, pointSize);
  }

  /** These options with another point size. */
  public RenderOptions withPointSize(double mm) {
    return new RenderOptions(grid, gridSize, points, lines, labels, mm);
  }
}
