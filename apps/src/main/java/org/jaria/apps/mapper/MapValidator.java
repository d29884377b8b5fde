package org.jaria.apps.mapper;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.jaria.apps.fx.PointLayer;
import org.jaria.apps.mapper.MapProblem.Severity;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;

/**
 * Checks a map before it is saved, the way a navigation program will use it: the home and goals
 * must be where a robot can stand (not inside a forbidden area, not in a wall), goals need unique
 * names, areas need a size.
 */
public final class MapValidator {

  /** A Pioneer 3-DX's radius, mm: a goal closer than this to a wall cannot be reached. */
  public static final double DEFAULT_ROBOT_RADIUS = 250;

  private final double robotRadius;

  /** A validator for robots of {@link #DEFAULT_ROBOT_RADIUS}. */
  public MapValidator() {
    this(DEFAULT_ROBOT_RADIUS);
  }

  /** A validator for robots of radius {@code robotRadius} mm. */
  public MapValidator(double robotRadius) {
    this.robotRadius = robotRadius;
  }

  /** Every problem of {@code content}, errors first, in map order. */
  public List<MapProblem> validate(MapContent content) {
    ArMapPoints p = content.points();
    return validate(content, new PointLayer(p.xArray(), p.yArray()));
  }

  /**
   * Every problem of {@code content}, errors first, in map order, using an index of its points that
   * the caller already has (the map view's).
   */
  public List<MapProblem> validate(MapContent content, PointLayer points) {
    List<MapProblem> errors = new ArrayList<>();
    List<MapProblem> warnings = new ArrayList<>();
    List<MapObjectEntry> areas = new ArrayList<>();
    boolean home = false;
    Map<String, Integer> goalNames = new HashMap<>();
    for (MapObjectEntry e : content.objects()) {
      ArMapObject o = e.object();
      if (o.isAreaType() && o.type().equals(ObjectKind.FORBIDDEN_AREA.type())) {
        areas.add(e);
      }
      if (o.isGoal() && !o.name().isBlank()) {
        goalNames.merge(o.name().toLowerCase(Locale.ROOT), 1, Integer::sum);
      }
    }
    for (MapObjectEntry e : content.objects()) {
      ArMapObject o = e.object();
      ObjectKind kind = ObjectKind.of(o.type());
      if (kind == ObjectKind.HOME) {
        home = true;
      }
      if (o.isAreaType()) {
        double[] size = MapGeometry.areaSize(o);
        if (size[0] < 1 || size[1] < 1) {
          warnings.add(
              new MapProblem(
                  Severity.WARNING,
                  describe(o)
                      + " has no area ("
                      + fmt(size[0])
                      + " × "
                      + fmt(size[1])
                      + " mm)"
                      + ": draw it again or delete it",
                  e.id()));
        }
        continue;
      }
      if (kind == null || o.hasFromTo()) {
        continue;
      }
      double x = o.pose().x();
      double y = o.pose().y();
      // Where the robot starts must be free, or the map does not work at all: an error. A goal
      // or dock no robot can reach is one place the robot refuses to go (ARIA's own columbia map
      // has such goals on purpose, to show path planning refusing): a warning.
      Severity unreachable = kind == ObjectKind.HOME ? Severity.ERROR : Severity.WARNING;
      List<MapProblem> list = unreachable == Severity.ERROR ? errors : warnings;
      for (MapObjectEntry a : areas) {
        if (a.object().contains(x, y)) {
          list.add(
              new MapProblem(
                  unreachable,
                  describe(o)
                      + " is inside a forbidden area: a robot may not go there; move it out or"
                      + " shrink the area",
                  e.id()));
          break;
        }
      }
      double wall = nearestObstacle(content, points, x, y);
      if (wall < robotRadius) {
        list.add(
            new MapProblem(
                unreachable,
                describe(o)
                    + " is "
                    + fmt(wall)
                    + " mm from a wall: a robot of radius "
                    + fmt(robotRadius)
                    + " mm cannot stand there; move it into free space",
                e.id()));
      }
      if (kind.isGoal()) {
        if (o.name().isBlank()) {
          warnings.add(
              new MapProblem(
                  Severity.WARNING,
                  describe(o) + " has no name: clients list goals by name; rename it",
                  e.id()));
        } else if (goalNames.getOrDefault(o.name().toLowerCase(Locale.ROOT), 0) > 1) {
          warnings.add(
              new MapProblem(
                  Severity.WARNING,
                  describe(o) + ": another goal has the same name; give each goal its own",
                  e.id()));
        }
      }
    }
    if (!home && !content.objects().isEmpty()) {
      warnings.add(
          new MapProblem(
              Severity.WARNING,
              "the map has no home: localization will start at the origin; add a home with the"
                  + " Home tool",
              -1));
    }
    errors.addAll(warnings);
    return errors;
  }

  /**
   * Distance from (x, y) to the nearest wall line, or to the nearest sensor point if that is closer
   * than the robot's radius, mm (infinite if neither is near).
   */
  double nearestObstacle(MapContent content, PointLayer points, double x, double y) {
    double best = Double.POSITIVE_INFINITY;
    for (MapLine l : content.lines()) {
      best = Math.min(best, MapGeometry.segmentDistance(l.segment(), x, y));
    }
    ArMapPoints p = content.points();
    // Only points within the radius matter; the index visits just the cells around (x, y).
    int i = points.nearest(x, y, Math.min(best, robotRadius));
    if (i >= 0) {
      best = Math.min(best, Math.hypot(p.x(i) - x, p.y(i) - y));
    }
    return best;
  }

  /** "goal 'Lobby' at (-1860, -22440)". */
  static String describe(ArMapObject o) {
    String what = ObjectKind.describe(o.type());
    String name = o.name().isBlank() ? "" : " '" + o.name() + "'";
    double[] c = MapGeometry.center(o);
    return what + name + " at (" + fmt(c[0]) + ", " + fmt(c[1]) + ")";
  }

  private static String fmt(double v) {
    return String.format(Locale.ROOT, "%.0f", v);
  }
}
