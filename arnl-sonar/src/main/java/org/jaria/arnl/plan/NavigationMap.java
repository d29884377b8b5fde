package org.jaria.arnl.plan;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.jaria.arnl.grid.DistanceField;
import org.jaria.arnl.grid.GridSpec;
import org.jaria.arnl.grid.MapRaster;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;

/**
 * Everything path planning precomputes from a map: the planning {@link CostGrid}, and two fine
 * distance fields (50 mm cells) for the local planner — clearance to anything the robot must not
 * touch or cross (walls, points, forbidden lines and areas), and distance to walls alone (to tell a
 * sonar echo of a mapped wall from an unmapped obstacle). Immutable.
 */
public final class NavigationMap implements LocalPlanner.ClearanceMap {

  /** Cell size of the fine fields, mm. */
  public static final double FINE_RES = 50;

  private final CostGrid grid;
  private final GridSpec fine;
  private final float[] clearance;
  private final float[] walls;
  private final List<ArMapObject> forbiddenAreas;

  private NavigationMap(
      CostGrid grid, GridSpec fine, float[] clearance, float[] walls, List<ArMapObject> areas) {
    this.grid = grid;
    this.fine = fine;
    this.clearance = clearance;
    this.walls = walls;
    this.forbiddenAreas = areas;
  }

  /**
   * Builds the maps.
   *
   * @param planRes planning cell size, mm
   * @param lethal closest the robot's centre may come to an obstacle on a planned path, mm
   * @param freeSpace clearance beyond which cells cost no extra, mm
   * @param weight extra cost of a cell at the lethal distance
   */
  public static NavigationMap build(
      ArMap map, double planRes, double lethal, double freeSpace, double weight) {
    CostGrid grid = CostGrid.build(map, planRes, lethal, freeSpace, weight);
    GridSpec fine = MapRaster.specFor(map, FINE_RES, 1000);
    boolean[] occ = MapRaster.walls(map, fine);
    float[] wallDist = DistanceField.compute(occ, fine, 5000);
    MapRaster.addForbidden(occ, fine, map);
    float[] clear = DistanceField.compute(occ, fine, 5000);
    List<ArMapObject> areas = new ArrayList<>();
    for (ArMapObject o : map.getMapObjects()) {
      if (o.isAreaType() && o.type().startsWith("Forbidden")) {
        areas.add(o);
      }
    }
    return new NavigationMap(grid, fine, clear, wallDist, List.copyOf(areas));
  }

  /** The planning grid. */
  public CostGrid grid() {
    return grid;
  }

  /** Clearance to walls, points and forbidden lines/areas at (x, y), mm; 0 outside the map. */
  @Override
  public double clearanceAt(double x, double y) {
    int k = fine.indexOf(x, y);
    return k < 0 ? 0 : clearance[k];
  }

  /** Distance to the nearest wall or point at (x, y), mm; 5000 outside the map. */
  public double wallDistanceAt(double x, double y) {
    int k = fine.indexOf(x, y);
    return k < 0 ? 5000 : walls[k];
  }

  /**
   * Range at which a sonar at (sx, sy) facing {@code axis} (radians) should hear a mapped wall or
   * point: the nearest one met by five rays spread across the cone of half-angle {@code coneHalf},
   * or {@code Double.MAX_VALUE} if none within {@code maxRange} mm.
   */
  public double expectedSonarRange(
      double sx, double sy, double axis, double coneHalf, double maxRange) {
    double best = Double.MAX_VALUE;
    for (int k = -2; k <= 2; k++) {
      double a = axis + coneHalf * k / 2;
      double dx = Math.cos(a);
      double dy = Math.sin(a);
      // Sphere tracing through the distance field: each step is as long as the clearance there.
      double t = FINE_RES;
      while (t <= Math.min(maxRange, best)) {
        double d = wallDistanceAt(sx + dx * t, sy + dy * t);
        if (d < 0.75 * FINE_RES) {
          best = Math.min(best, t);
          break;
        }
        t += Math.max(0.5 * FINE_RES, d - 0.75 * FINE_RES);
      }
    }
    return best;
  }

  /** Whether (x, y) lies on the planning grid. */
  public boolean inBounds(double x, double y) {
    return grid.spec().indexOf(x, y) >= 0;
  }

  /** The forbidden area containing (x, y), if any. */
  public Optional<ArMapObject> forbiddenAreaAt(double x, double y) {
    for (ArMapObject o : forbiddenAreas) {
      if (o.contains(x, y)) {
        return Optional.of(o);
      }
    }
    return Optional.empty();
  }
}
