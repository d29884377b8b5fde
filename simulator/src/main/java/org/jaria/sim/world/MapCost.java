package org.jaria.sim.world;

import java.util.List;
import org.jaria.geom.ArLineSegment;

/**
 * What a map costs the simulator, counted from what it holds before anything is built: its wall
 * lines, its points, and how many entries the spatial index ({@link SegmentIndex}) would record
 * (one per grid cell a line crosses or a point's disc touches; a long line crosses thousands).
 * Memory and build time follow these, not the file's size.
 *
 * @param lines wall lines
 * @param points DATA points
 * @param cellEntries at most this many (cell, line or point) entries in the index
 */
public record MapCost(long lines, long points, long cellEntries) {

  /**
   * The cost of a map with {@code lines} and the points ({@code xs[i]}, {@code ys[i]}), each a disc
   * of {@code radius}: computed with the grid the index would pick, in one pass, building nothing.
   */
  public static MapCost of(List<ArLineSegment> lines, int[] xs, int[] ys, double radius) {
    int n = lines.size() + xs.length;
    if (n == 0) {
      return new MapCost(0, 0, 0);
    }
    double x0 = Double.POSITIVE_INFINITY;
    double y0 = Double.POSITIVE_INFINITY;
    double x1 = Double.NEGATIVE_INFINITY;
    double y1 = Double.NEGATIVE_INFINITY;
    for (ArLineSegment s : lines) {
      x0 = Math.min(x0, Math.min(s.x1(), s.x2()));
      y0 = Math.min(y0, Math.min(s.y1(), s.y2()));
      x1 = Math.max(x1, Math.max(s.x1(), s.x2()));
      y1 = Math.max(y1, Math.max(s.y1(), s.y2()));
    }
    for (int i = 0; i < xs.length; i++) {
      x0 = Math.min(x0, xs[i] - radius);
      y0 = Math.min(y0, ys[i] - radius);
      x1 = Math.max(x1, xs[i] + radius);
      y1 = Math.max(y1, ys[i] + radius);
    }
    // the index's extent is one millimetre wider on every side
    double w = x1 - x0 + 2;
    double h = y1 - y0 + 2;
    double cell = SegmentIndex.cellFor(w, h, n, 0);
    long nx = Math.max(1, (long) Math.ceil(w / cell));
    long ny = Math.max(1, (long) Math.ceil(h / cell));
    long grid = nx * ny;
    long entries = 0;
    for (ArLineSegment s : lines) {
      long b = SegmentIndex.segmentCellsBound(s.x1(), s.y1(), s.x2(), s.y2(), cell);
      entries += Math.min(b, Math.min(grid, nx + 2 * ny + 1));
    }
    if (xs.length > 0) {
      entries += xs.length * Math.min(grid, SegmentIndex.discCellsBound(radius, cell));
    }
    return new MapCost(lines.size(), xs.length, entries);
  }
}
