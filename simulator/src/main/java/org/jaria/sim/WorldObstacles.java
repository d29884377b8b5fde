package org.jaria.sim;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.sim.camera.ColoredObjects;
import org.jaria.sim.world.WorldGeometry;
import org.jaria.sim.world.WorldMap;

/**
 * A world's map and the obstacles injected into it: replacing the map (and moving the robots to
 * free spots near its start), adding and removing obstacles. Runs under the world's lock; the index
 * of everything solid is rebuilt lazily by {@link WorldStatics}.
 */
final class WorldObstacles {

  private final WorldStatics statics;
  private final WorldGeometry geometry;
  private final ColoredObjects colored;

  WorldObstacles(WorldStatics statics, WorldGeometry geometry, ColoredObjects colored) {
    this.statics = statics;
    this.geometry = geometry;
    this.colored = colored;
  }

  /** Replaces the map with an ARIA map: walls, start position and coloured objects. */
  void loadMap(ArMap newMap, String source, List<RobotSlot> slots) {
    setMap(MapSupport.fromArMap(newMap, source), slots);
    colored.replaceFromMap(newMap);
  }

  /** Replaces the map; robots move to free spots near its start position. */
  void setMap(WorldMap m, List<RobotSlot> slots) {
    statics.setMap(m);
    Placement.replaceAll(slots, m.home(), geometry);
  }

  WorldMap map() {
    return statics.map();
  }

  boolean haveMap() {
    return !statics.map().isEmpty();
  }

  SimObstacle inject(List<ArLineSegment> walls) {
    return statics.add(walls);
  }

  boolean remove(SimObstacle o) {
    return statics.remove(o);
  }

  List<SimObstacle> list() {
    return statics.list();
  }
}
