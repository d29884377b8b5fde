package org.jaria.arnl.mcl;

import org.jaria.arnl.grid.DistanceField;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.arnl.grid.MapRaster;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;

/**
 * Where a range sensor meets the map: the surfaces of its walls, on the grid of a {@link
 * LikelihoodField}.
 *
 * <p>A DATA point of a map stands for an occupied square of the map's {@code Resolution} (a laser
 * map is a grid of hit cells, and JAria's simulator blocks a disc of half a resolution around each
 * point), so a beam ends half a resolution <em>before</em> the point, on the face. The first laser
 * field drew a wall at its points instead, and drew a wall lying on a cell border in the cell on
 * its far side: both put walls behind the faces the laser sees, and a laser looking ahead pulled
 * the estimate forward (a robot standing still settled about 65 mm ahead of its true pose; the
 * tracking benchmark showed +38 mm along the track). So the distances are measured to the faces of
 * walls: to the rim of a disc of half the map's resolution around each point, and to lines as thin
 * walls; and the grid is laid out so that cell centres fall on multiples of the cell size, where
 * map coordinates usually lie.
 */
final class MapSurfaces {

  private MapSurfaces() {}

  /** A grid of {@code res} mm cells, centred on multiples of {@code res}, covering the map. */
  static GridSpec centredSpec(ArMap map, double res) {
    GridSpec g = MapRaster.specFor(map, res, 1000);
    return new GridSpec(
        g.originX() - res / 2, g.originY() - res / 2, res, g.width() + 1, g.height() + 1);
  }

  /**
   * Distance from every cell centre to the nearest wall face, mm (capped at {@code cap}), and in
   * {@code solid} (same size as the grid) the cells inside a wall. Points count as discs of half
   * the map's resolution: the distance to one is |distance to its centre − radius|, zero on its rim
   * and growing inside it as outside, so that an echo must fall on the face. Lines are thin walls;
   * a line's cells under a point's disc add nothing (the disc's face hides them).
   */
  static float[] faceDistances(ArMap map, GridSpec g, double cap, boolean[] solid) {
    int n = g.size();
    boolean[] centres = new boolean[n];
    ArMapPoints p = map.getPoints();
    for (int k = 0; k < p.size(); k++) {
      MapRaster.addPoint(centres, g, p.x(k), p.y(k));
    }
    double radius = p.size() == 0 ? 0 : Math.max(0, map.getResolution() / 2.0);
    float[] toPoint = DistanceField.compute(centres, g, cap + radius);
    boolean[] lines = new boolean[n];
    for (ArLineSegment l : map.getLines()) {
      MapRaster.addSegment(lines, g, l.x1(), l.y1(), l.x2(), l.y2());
    }
    for (int k = 0; k < n; k++) {
      boolean inDisc = p.size() > 0 && toPoint[k] < radius;
      solid[k] = lines[k] || inDisc || centres[k];
      lines[k] &= !(p.size() > 0 && toPoint[k] <= radius);
    }
    float[] toLine = DistanceField.compute(lines, g, cap);
    float[] out = new float[n];
    for (int k = 0; k < n; k++) {
      double face = p.size() == 0 ? cap : Math.abs(toPoint[k] - radius);
      out[k] = (float) Math.min(cap, Math.min(face, toLine[k]));
    }
    return out;
  }
}
