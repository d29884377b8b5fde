package org.jaria.web.model;

import java.util.List;
import java.util.Objects;

/**
 * The still part of the picture: a map's walls, sensor points, goals and forbidden areas, in
 * millimetres in the map's frame. It changes only when a new map is loaded, so it is sent once to
 * each viewer and again on a change.
 *
 * @param name the map's name (its file name, or a description)
 * @param lines wall segments, two points each (x1, y1, x2, y2 of segment 0, then of segment 1...)
 * @param points the map's sensor points (the DATA section)
 * @param goals named goals (and the robot's home, docks)
 * @param forbiddenLines forbidden lines, two points each as {@code lines}
 * @param forbiddenAreas forbidden areas, each a closed polygon
 * @param bounds a box around all of it
 */
public record MapLayer(
    String name,
    Points lines,
    Points points,
    List<Goal> goals,
    Points forbiddenLines,
    List<Points> forbiddenAreas,
    Bounds bounds) {

  /** A map with nothing on it. */
  public static final MapLayer EMPTY =
      new MapLayer(
          "empty",
          Points.EMPTY,
          Points.EMPTY,
          List.of(),
          Points.EMPTY,
          List.of(),
          new Bounds(-5000, -5000, 5000, 5000));

  /** Checks and copies. */
  public MapLayer {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(lines, "lines");
    Objects.requireNonNull(points, "points");
    Objects.requireNonNull(forbiddenLines, "forbiddenLines");
    Objects.requireNonNull(bounds, "bounds");
    goals = List.copyOf(goals);
    forbiddenAreas = List.copyOf(forbiddenAreas);
    if (lines.size() % 2 != 0 || forbiddenLines.size() % 2 != 0) {
      throw new IllegalArgumentException("line segments need two points each");
    }
  }

  /** The number of wall segments. */
  public int lineCount() {
    return lines.size() / 2;
  }

  /**
   * A named place on the map.
   *
   * @param name its name
   * @param kind what it is ("Goal", "GoalWithHeading", "RobotHome", "Dock", ...)
   * @param x x, mm
   * @param y y, mm
   * @param thDeg heading, degrees (meaningful when {@code hasHeading})
   * @param hasHeading whether the place says which way to face
   */
  public record Goal(
      String name, String kind, double x, double y, double thDeg, boolean hasHeading) {}

  /**
   * A box, mm.
   *
   * @param minX least x
   * @param minY least y
   * @param maxX greatest x
   * @param maxY greatest y
   */
  public record Bounds(double minX, double minY, double maxX, double maxY) {

    /** A box around {@code p} (a unit box around the origin if {@code p} is empty). */
    public static Bounds around(Points... sets) {
      double x0 = Double.POSITIVE_INFINITY;
      double y0 = Double.POSITIVE_INFINITY;
      double x1 = Double.NEGATIVE_INFINITY;
      double y1 = Double.NEGATIVE_INFINITY;
      for (Points p : sets) {
        for (int i = 0; i < p.size(); i++) {
          x0 = Math.min(x0, p.x(i));
          y0 = Math.min(y0, p.y(i));
          x1 = Math.max(x1, p.x(i));
          y1 = Math.max(y1, p.y(i));
        }
      }
      return x0 > x1 ? new Bounds(-1000, -1000, 1000, 1000) : new Bounds(x0, y0, x1, y1);
    }
  }
}
