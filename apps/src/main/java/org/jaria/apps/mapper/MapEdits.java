package org.jaria.apps.mapper;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;
import java.util.Set;
import java.util.function.LongSupplier;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;

/** The map editor's edits: add, delete, move, and change one object (rename, rotate...). */
public final class MapEdits {

  private MapEdits() {}

  /** Adds wall lines and objects (appended after the existing ones, as a map file lists them). */
  public static MapEdit add(String name, List<ArLineSegment> lines, List<ArMapObject> objects) {
    return new Add(name, List.copyOf(lines), List.copyOf(objects), ArMapPoints.EMPTY);
  }

  /** Adds one wall line. */
  public static MapEdit addLine(ArLineSegment line) {
    return add("Add wall", List.of(line), List.of());
  }

  /** Adds one object, named after its type ("Add Goal"). */
  public static MapEdit addObject(ArMapObject o) {
    return add("Add " + ObjectKind.describe(o.type()), List.of(), List.of(o));
  }

  /** Adds sensor points at the given coordinates (mm). */
  public static MapEdit addPoints(int[] xs, int[] ys) {
    return new Add("Add point", List.of(), List.of(), ArMapPoints.of(xs, ys));
  }

  /** Deletes the items with the given editor numbers and the points with the given indices. */
  public static MapEdit delete(Set<Long> ids, BitSet points) {
    return new Delete(Set.copyOf(ids), (BitSet) points.clone());
  }

  /** Moves items and points by (dx, dy) mm. */
  public static MapEdit move(Set<Long> ids, BitSet points, double dx, double dy) {
    return new Move(Set.copyOf(ids), (BitSet) points.clone(), dx, dy);
  }

  /** Replaces one object, keeping its place and number (rename, rotate, edit). */
  public static MapEdit replace(String name, long id, ArMapObject replacement) {
    return new Replace(name, id, replacement);
  }

  private record Add(
      String name, List<ArLineSegment> lines, List<ArMapObject> objects, ArMapPoints added)
      implements MapEdit {
    @Override
    public MapContent apply(MapContent before, LongSupplier newIds) {
      List<MapLine> l = new ArrayList<>(before.lines());
      for (ArLineSegment s : lines) {
        l.add(new MapLine(newIds.getAsLong(), s));
      }
      List<MapObjectEntry> o = new ArrayList<>(before.objects());
      for (ArMapObject m : objects) {
        o.add(new MapObjectEntry(newIds.getAsLong(), m));
      }
      ArMapPoints p = before.points();
      if (!added.isEmpty()) {
        int n = p.size();
        int[] nx = Arrays.copyOf(p.xArray(), n + added.size());
        int[] ny = Arrays.copyOf(p.yArray(), n + added.size());
        System.arraycopy(added.xArray(), 0, nx, n, added.size());
        System.arraycopy(added.yArray(), 0, ny, n, added.size());
        p = ArMapPoints.of(nx, ny);
      }
      return new MapContent(l, p, o);
    }
  }

  private record Delete(Set<Long> ids, BitSet points) implements MapEdit {
    @Override
    public String name() {
      int n = ids.size() + points.cardinality();
      return n == 1 ? "Delete item" : "Delete " + n + " items";
    }

    @Override
    public MapContent apply(MapContent before, LongSupplier newIds) {
      List<MapLine> l = new ArrayList<>(before.lines());
      l.removeIf(x -> ids.contains(x.id()));
      List<MapObjectEntry> o = new ArrayList<>(before.objects());
      o.removeIf(x -> ids.contains(x.id()));
      ArMapPoints p = before.points();
      if (!points.isEmpty()) {
        int[] xs = p.xArray();
        int[] ys = p.yArray();
        int n = 0;
        for (int i = 0; i < xs.length; i++) {
          if (!points.get(i)) {
            xs[n] = xs[i];
            ys[n] = ys[i];
            n++;
          }
        }
        p = ArMapPoints.of(Arrays.copyOf(xs, n), Arrays.copyOf(ys, n));
      }
      return new MapContent(l, p, o);
    }
  }

  private record Move(Set<Long> ids, BitSet points, double dx, double dy) implements MapEdit {
    @Override
    public String name() {
      return "Move";
    }

    @Override
    public MapContent apply(MapContent before, LongSupplier newIds) {
      List<MapLine> l = new ArrayList<>(before.lines().size());
      for (MapLine x : before.lines()) {
        if (ids.contains(x.id())) {
          ArLineSegment s = x.segment();
          l.add(
              new MapLine(
                  x.id(), new ArLineSegment(s.x1() + dx, s.y1() + dy, s.x2() + dx, s.y2() + dy)));
        } else {
          l.add(x);
        }
      }
      List<MapObjectEntry> o = new ArrayList<>(before.objects().size());
      for (MapObjectEntry e : before.objects()) {
        o.add(
            ids.contains(e.id())
                ? new MapObjectEntry(e.id(), MapGeometry.translate(e.object(), dx, dy))
                : e);
      }
      ArMapPoints p = before.points();
      if (!points.isEmpty()) {
        int[] xs = p.xArray();
        int[] ys = p.yArray();
        int ix = (int) Math.round(dx);
        int iy = (int) Math.round(dy);
        for (int i = points.nextSetBit(0); i >= 0 && i < xs.length; i = points.nextSetBit(i + 1)) {
          xs[i] += ix;
          ys[i] += iy;
        }
        p = ArMapPoints.of(xs, ys);
      }
      return new MapContent(l, p, o);
    }
  }

  private record Replace(String name, long id, ArMapObject replacement) implements MapEdit {
    @Override
    public MapContent apply(MapContent before, LongSupplier newIds) {
      List<MapObjectEntry> o = new ArrayList<>(before.objects());
      for (int i = 0; i < o.size(); i++) {
        if (o.get(i).id() == id) {
          o.set(i, new MapObjectEntry(id, replacement));
          return before.withObjects(o);
        }
      }
      throw new IllegalArgumentException("the object to change is no longer on the map");
    }
  }
}
