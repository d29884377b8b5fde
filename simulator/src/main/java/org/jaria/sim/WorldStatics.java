package org.jaria.sim;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jaria.geom.ArLineSegment;
import org.jaria.sim.world.WorldGeometry;
import org.jaria.sim.world.WorldMap;

/**
 * The still part of a world: the map and the injected obstacles, and their spatial index, rebuilt
 * lazily after a change. Guarded by the world's lock.
 */
final class WorldStatics {

  private final WorldGeometry geometry;
  private final Map<Integer, SimObstacle> obstacles = new LinkedHashMap<>();
  private WorldMap map;
  private boolean dirty = true;
  private int nextId = 1;

  WorldStatics(WorldMap map, WorldGeometry geometry) {
    this.map = map;
    this.geometry = geometry;
  }

  WorldMap map() {
    return map;
  }

  void setMap(WorldMap m) {
    map = m;
    dirty = true;
    rebuild();
  }

  SimObstacle add(List<ArLineSegment> walls) {
    SimObstacle o = new SimObstacle(nextId++, walls);
    obstacles.put(o.id(), o);
    dirty = true;
    return o;
  }

  boolean remove(SimObstacle o) {
    boolean removed = obstacles.remove(o.id()) != null;
    dirty |= removed;
    return removed;
  }

  List<SimObstacle> list() {
    return List.copyOf(obstacles.values());
  }

  /** Rebuilds the index if the map or the obstacles changed. */
  void rebuild() {
    if (dirty) {
      List<List<ArLineSegment>> walls = new ArrayList<>();
      for (SimObstacle o : obstacles.values()) {
        walls.add(o.segments());
      }
      geometry.setStatics(map.buildIndex(walls));
      dirty = false;
    }
  }

  /** The four walls of a {@code w} × {@code h} box centred at (cx, cy), turned {@code thDeg}. */
  static List<ArLineSegment> box(double cx, double cy, double w, double h, double thDeg) {
    double r = Math.toRadians(thDeg);
    double c = Math.cos(r);
    double s = Math.sin(r);
    double[][] local = {{w / 2, h / 2}, {-w / 2, h / 2}, {-w / 2, -h / 2}, {w / 2, -h / 2}};
    List<ArLineSegment> walls = new ArrayList<>(4);
    for (int i = 0; i < 4; i++) {
      double[] a = local[i];
      double[] b = local[(i + 1) % 4];
      walls.add(
          new ArLineSegment(
              cx + c * a[0] - s * a[1],
              cy + s * a[0] + c * a[1],
              cx + c * b[0] - s * b[1],
              cy + s * b[0] + c * b[1]));
    }
    return walls;
  }
}
