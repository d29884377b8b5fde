package org.jaria.arnl.grid;

import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;

/**
 * Draws map content into occupancy grids ({@code boolean[]}, true = obstacle): wall lines and
 * sensor points (what sensors see), and forbidden lines and areas (what only the planner avoids).
 * Lines are drawn 4-connected, so that no 8-connected path can slip diagonally through them.
 */
public final class MapRaster {

  private MapRaster() {}

  /**
   * The grid covering everything on {@code map} (lines, points, objects) plus {@code margin} mm on
   * every side, with cells of {@code res} mm.
   */
  public static GridSpec specFor(ArMap map, double res, double margin) {
    double minX = Double.POSITIVE_INFINITY;
    double minY = Double.POSITIVE_INFINITY;
    double maxX = Double.NEGATIVE_INFINITY;
    double maxY = Double.NEGATIVE_INFINITY;
    for (ArLineSegment l : map.getLines()) {
      minX = Math.min(minX, Math.min(l.x1(), l.x2()));
      minY = Math.min(minY, Math.min(l.y1(), l.y2()));
      maxX = Math.max(maxX, Math.max(l.x1(), l.x2()));
      maxY = Math.max(maxY, Math.max(l.y1(), l.y2()));
    }
    ArMapPoints p = map.getPoints();
    for (int i = 0; i < p.size(); i++) {
      minX = Math.min(minX, p.x(i));
      minY = Math.min(minY, p.y(i));
      maxX = Math.max(maxX, p.x(i));
      maxY = Math.max(maxY, p.y(i));
    }
    for (ArMapObject o : map.getMapObjects()) {
      minX = Math.min(minX, o.pose().x());
      minY = Math.min(minY, o.pose().y());
      maxX = Math.max(maxX, o.pose().x());
      maxY = Math.max(maxY, o.pose().y());
    }
    if (minX > maxX) {
      minX = -1000;
      minY = -1000;
      maxX = 1000;
      maxY = 1000;
    }
    return GridSpec.covering(minX, minY, maxX, maxY, margin, res);
  }

  /** The map's walls: LINES and DATA points. */
  public static boolean[] walls(ArMap map, GridSpec g) {
    boolean[] occ = new boolean[g.size()];
    for (ArLineSegment l : map.getLines()) {
      addSegment(occ, g, l.x1(), l.y1(), l.x2(), l.y2());
    }
    ArMapPoints p = map.getPoints();
    for (int i = 0; i < p.size(); i++) {
      addPoint(occ, g, p.x(i), p.y(i));
    }
    return occ;
  }

  /** Adds the map's forbidden lines and (filled) forbidden areas to {@code occ}. */
  public static void addForbidden(boolean[] occ, GridSpec g, ArMap map) {
    for (ArMapObject o : map.getMapObjects()) {
      if (!o.hasFromTo() || !o.type().startsWith("Forbidden")) {
        continue;
      }
      for (ArLineSegment s : o.getFromToSegments()) {
        addSegment(occ, g, s.x1(), s.y1(), s.x2(), s.y2());
      }
      if (o.isAreaType()) {
        fillArea(occ, g, o);
      }
    }
  }

  private static void fillArea(boolean[] occ, GridSpec g, ArMapObject o) {
    double minX = Double.POSITIVE_INFINITY;
    double minY = Double.POSITIVE_INFINITY;
    double maxX = Double.NEGATIVE_INFINITY;
    double maxY = Double.NEGATIVE_INFINITY;
    for (ArLineSegment s : o.getFromToSegments()) {
      minX = Math.min(minX, Math.min(s.x1(), s.x2()));
      minY = Math.min(minY, Math.min(s.y1(), s.y2()));
      maxX = Math.max(maxX, Math.max(s.x1(), s.x2()));
      maxY = Math.max(maxY, Math.max(s.y1(), s.y2()));
    }
    int i0 = Math.max(0, g.cellX(minX));
    int i1 = Math.min(g.width() - 1, g.cellX(maxX));
    int j0 = Math.max(0, g.cellY(minY));
    int j1 = Math.min(g.height() - 1, g.cellY(maxY));
    for (int j = j0; j <= j1; j++) {
      for (int i = i0; i <= i1; i++) {
        if (o.contains(g.centerX(i), g.centerY(j))) {
          occ[j * g.width() + i] = true;
        }
      }
    }
  }

  /** Marks the cell holding (x, y). */
  public static void addPoint(boolean[] occ, GridSpec g, double x, double y) {
    int k = g.indexOf(x, y);
    if (k >= 0) {
      occ[k] = true;
    }
  }

  /** Marks every cell the segment passes through (a 4-connected chain of cells). */
  public static void addSegment(
      boolean[] occ, GridSpec g, double x1, double y1, double x2, double y2) {
    double len = Math.hypot(x2 - x1, y2 - y1);
    int steps = Math.max(1, (int) Math.ceil(len / (g.res() / 3)));
    int pi = g.cellX(x1);
    int pj = g.cellY(y1);
    mark(occ, g, pi, pj);
    for (int s = 1; s <= steps; s++) {
      double t = (double) s / steps;
      int i = g.cellX(x1 + (x2 - x1) * t);
      int j = g.cellY(y1 + (y2 - y1) * t);
      if (i != pi && j != pj) {
        // A diagonal step: fill the corner so that the chain stays 4-connected.
        mark(occ, g, i, pj);
      }
      mark(occ, g, i, j);
      pi = i;
      pj = j;
    }
  }

  private static void mark(boolean[] occ, GridSpec g, int i, int j) {
    if (g.inside(i, j)) {
      occ[j * g.width() + i] = true;
    }
  }
}
