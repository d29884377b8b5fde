package org.jaria.web.source;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;
import org.jaria.sim.world.WorldMap;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;

/** Builds {@link MapLayer}s from ARIA's maps and from the simulator's physical maps. */
public final class MapLayers {

  private MapLayers() {}

  /** Everything a map file holds that a viewer draws: walls, points, goals, forbidden places. */
  public static MapLayer of(ArMap map, String name) {
    Points lines = segments(map.getLines());
    ArMapPoints mp = map.getPoints();
    Points.Builder pts = Points.builder(mp.size());
    for (int i = 0; i < mp.size(); i++) {
      pts.add(mp.x(i), mp.y(i));
    }
    List<MapLayer.Goal> goals = new ArrayList<>();
    List<ArLineSegment> forbiddenLines = new ArrayList<>();
    List<Points> areas = new ArrayList<>();
    for (ArMapObject o : map.getMapObjects()) {
      if (o.isGoal() || o.type().equals("RobotHome") || o.type().equals("Dock")) {
        boolean heading = !o.type().equals("Goal");
        goals.add(
            new MapLayer.Goal(
                o.name(), o.type(), o.pose().x(), o.pose().y(), o.pose().th(), heading));
      } else if (o.isLineType() && o.type().startsWith("Forbidden")) {
        forbiddenLines.add(o.getFromToSegment());
      } else if (o.isAreaType() && o.type().startsWith("Forbidden")) {
        Points.Builder corners = Points.builder(4);
        for (ArLineSegment s : o.getFromToSegments()) {
          corners.add(s.x1(), s.y1());
        }
        areas.add(corners.build());
      }
    }
    Points points = pts.build();
    return new MapLayer(
        name,
        lines,
        points,
        goals,
        segments(forbiddenLines),
        areas,
        MapLayer.Bounds.around(lines, points));
  }

  /** The simulator's physical map: walls and points only (it keeps no goals). */
  public static MapLayer of(WorldMap map) {
    Points lines = segments(map.lines());
    Points.Builder pts = Points.builder(map.pointCount());
    int[] xs = map.pointX();
    int[] ys = map.pointY();
    for (int i = 0; i < xs.length; i++) {
      pts.add(xs[i], ys[i]);
    }
    Points points = pts.build();
    return new MapLayer(
        map.source(),
        lines,
        points,
        List.of(
            new MapLayer.Goal(
                "home", "RobotHome", map.home().x(), map.home().y(), map.home().th(), true)),
        Points.EMPTY,
        List.of(),
        MapLayer.Bounds.around(lines, points));
  }

  private static Points segments(List<ArLineSegment> segs) {
    Points.Builder b = Points.builder(2 * segs.size());
    for (ArLineSegment s : segs) {
      b.add(s.x1(), s.y1()).add(s.x2(), s.y2());
    }
    return b.build();
  }
}
