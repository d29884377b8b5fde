package org.jaria.sim;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapPoints;
import org.jaria.map.MapFormatException;
import org.jaria.sim.world.MapCost;
import org.jaria.sim.world.WorldMap;

/**
 * Turns ArMap documents into what the simulator needs: LINES and DATA points are solid (each point
 * blocks a disc of half the map's resolution); forbidden lines and areas are only for path planners
 * and are ignored; robots start at the first RobotHome, else Dock, else the origin.
 */
public final class MapSupport {

  /** Radius a DATA point blocks when the map gives no resolution, mm. */
  public static final double DEFAULT_POINT_RADIUS = 10;

  private MapSupport() {}

  /**
   * A short name for a map's source: "office" for "bundled:office", "hall" for "/maps/hall.map".
   */
  static String shortName(String source) {
    String s = source == null || source.isBlank() ? "map" : source;
    s =
        s.substring(
            Math.max(s.lastIndexOf('/'), Math.max(s.lastIndexOf('\\'), s.lastIndexOf(':'))) + 1);
    return s.endsWith(".map") ? s.substring(0, s.length() - 4) : s;
  }

  /**
   * The physical content of {@code map}, if it fits the simulator's {@link MapBudget#DEFAULT}.
   *
   * @throws MapBudget.MapTooBigException if it does not (checked before anything is built)
   */
  public static WorldMap fromArMap(ArMap map, String source) {
    return fromArMap(map, source, MapBudget.DEFAULT);
  }

  /**
   * The physical content of {@code map}, if it fits {@code budget}.
   *
   * @throws MapBudget.MapTooBigException if it does not (checked before anything is built)
   */
  public static WorldMap fromArMap(ArMap map, String source, MapBudget budget) {
    List<ArLineSegment> lines = map.getLines();
    ArMapPoints pts = map.getPoints();
    int n = pts.size();
    // counts first: they alone bound what the copies below cost
    budget.check(new MapCost(lines.size(), n, 0), source);
    int[] xs = new int[n];
    int[] ys = new int[n];
    for (int i = 0; i < n; i++) {
      xs[i] = pts.x(i);
      ys[i] = pts.y(i);
    }
    double radius = pointRadius(map);
    budget.check(MapCost.of(lines, xs, ys, radius), source);
    ArPose home = map.findHomePose().orElse(ArPose.ORIGIN);
    return new WorldMap(source, lines, xs, ys, radius, home);
  }

  /** What {@code map} costs the simulator (see {@link MapBudget}). */
  public static MapCost cost(ArMap map) {
    ArMapPoints pts = map.getPoints();
    int n = pts.size();
    int[] xs = new int[n];
    int[] ys = new int[n];
    for (int i = 0; i < n; i++) {
      xs[i] = pts.x(i);
      ys[i] = pts.y(i);
    }
    return MapCost.of(map.getLines(), xs, ys, pointRadius(map));
  }

  private static double pointRadius(ArMap map) {
    int res = map.getResolution();
    return res > 0 ? res / 2.0 : DEFAULT_POINT_RADIUS;
  }

  /**
   * Reads a map file.
   *
   * @throws IOException if the file cannot be read, or (with the parser's "file:line: what"
   *     message) if a line is malformed, or if the map is over the simulator's {@link MapBudget}
   */
  public static WorldMap load(Path file) throws IOException {
    try {
      return fromArMap(ArMap.readFile(file), file.toString());
    } catch (MapFormatException | MapBudget.MapTooBigException e) {
      throw new IOException(e.getMessage(), e);
    }
  }

  /** One of the maps bundled with JAria ("office", "hall"). */
  public static WorldMap bundled(String name) {
    return fromArMap(ArMap.loadBundled(name), "bundled:" + name);
  }
}
