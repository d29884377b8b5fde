package org.jaria.apps.mapper;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;

/**
 * What the editor shows and edits at one moment: wall lines, sensor points and map objects.
 * Immutable, so an undo step is simply the content before and after an edit; a 63k-point map shares
 * its points between steps until an edit changes them.
 *
 * @param lines the wall lines, in file order
 * @param points the sensor points
 * @param objects the map objects, in file order
 */
public record MapContent(List<MapLine> lines, ArMapPoints points, List<MapObjectEntry> objects) {

  /** An empty map. */
  public static final MapContent EMPTY = new MapContent(List.of(), ArMapPoints.EMPTY, List.of());

  /** Copies the lists. */
  public MapContent {
    lines = List.copyOf(lines);
    objects = List.copyOf(objects);
  }

  /** This content with other lines. */
  public MapContent withLines(List<MapLine> l) {
    return new MapContent(l, points, objects);
  }

  /** This content with other points. */
  public MapContent withPoints(ArMapPoints p) {
    return new MapContent(lines, p, objects);
  }

  /** This content with other objects. */
  public MapContent withObjects(List<MapObjectEntry> o) {
    return new MapContent(lines, points, o);
  }

  /** The line with editor number {@code id}. */
  public Optional<MapLine> findLine(long id) {
    return lines.stream().filter(l -> l.id() == id).findFirst();
  }

  /** The object with editor number {@code id}. */
  public Optional<MapObjectEntry> findObject(long id) {
    return objects.stream().filter(o -> o.id() == id).findFirst();
  }

  /** Whether an item (line or object) with editor number {@code id} exists. */
  public boolean contains(long id) {
    return findLine(id).isPresent() || findObject(id).isPresent();
  }

  /** The bare segments, in order. */
  public List<ArLineSegment> segments() {
    List<ArLineSegment> out = new ArrayList<>(lines.size());
    for (MapLine l : lines) {
      out.add(l.segment());
    }
    return out;
  }

  /** The bare objects, in order. */
  public List<ArMapObject> mapObjects() {
    List<ArMapObject> out = new ArrayList<>(objects.size());
    for (MapObjectEntry e : objects) {
      out.add(e.object());
    }
    return out;
  }

  /**
   * The bounding box of everything (points, lines, objects) as {minX, minY, maxX, maxY}, or a 10 m
   * square around the origin for an empty map.
   */
  public double[] bounds() {
    double[] b = {
      Double.POSITIVE_INFINITY,
      Double.POSITIVE_INFINITY,
      Double.NEGATIVE_INFINITY,
      Double.NEGATIVE_INFINITY
    };
    for (int i = 0; i < points.size(); i++) {
      grow(b, points.x(i), points.y(i));
    }
    for (MapLine l : lines) {
      grow(b, l.segment().x1(), l.segment().y1());
      grow(b, l.segment().x2(), l.segment().y2());
    }
    for (MapObjectEntry e : objects) {
      if (!e.object().hasFromTo()) {
        // Areas written as Mapper3 does have pose 0 0 0: only their corners count.
        grow(b, e.object().pose().x(), e.object().pose().y());
      }
      for (ArLineSegment s : e.object().getFromToSegments()) {
        grow(b, s.x1(), s.y1());
        grow(b, s.x2(), s.y2());
      }
    }
    if (b[0] > b[2]) {
      return new double[] {-5000, -5000, 5000, 5000};
    }
    return b;
  }

  private static void grow(double[] b, double x, double y) {
    b[0] = Math.min(b[0], x);
    b[1] = Math.min(b[1], y);
    b[2] = Math.max(b[2], x);
    b[3] = Math.max(b[3], y);
  }
}
