package org.jaria.apps.mapper;

import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.map.ArMapObject;

/**
 * Geometry of map objects the editor needs: moving and rotating them, their centre and size, and
 * how far a point is from them (for picking with the mouse).
 *
 * <p>Area objects follow {@link ArMapObject}'s convention: the corners are stored in the frame
 * rotated by the pose's heading about the map origin. Moving an area therefore moves its pose and
 * its corners (the latter expressed in that rotated frame); rotating it keeps its centre.
 */
public final class MapGeometry {

  private MapGeometry() {}

  /** The object moved by (dx, dy) mm. */
  public static ArMapObject translate(ArMapObject o, double dx, double dy) {
    ArPose p = o.pose();
    if (!o.hasFromTo()) {
      return with(o, new ArPose(p.x() + dx, p.y() + dy, p.th()), null, null);
    }
    if (o.isLineType()) {
      return with(
          o,
          new ArPose(p.x() + dx, p.y() + dy, p.th()),
          shift(o.fromPose(), dx, dy),
          shift(o.toPose(), dx, dy));
    }
    double r = Math.toRadians(p.th());
    double c = Math.cos(r);
    double s = Math.sin(r);
    double ux = dx * c + dy * s;
    double uy = -dx * s + dy * c;
    // Mapper3 writes unrotated areas with pose 0 0 0; keep that form while th stays 0.
    ArPose pose =
        (p.x() == 0 && p.y() == 0 && p.th() == 0) ? p : new ArPose(p.x() + dx, p.y() + dy, p.th());
    return with(o, pose, shift(o.fromPose(), ux, uy), shift(o.toPose(), ux, uy));
  }

  private static ArPose shift(ArPose p, double dx, double dy) {
    return new ArPose(p.x() + dx, p.y() + dy, p.th());
  }

  private static ArMapObject with(ArMapObject o, ArPose pose, ArPose from, ArPose to) {
    return new ArMapObject(
        o.type(), pose, o.description(), o.iconName(), o.name(), o.hasFromTo(), from, to);
  }

  /** The object with another name (label). */
  public static ArMapObject renamed(ArMapObject o, String name) {
    return new ArMapObject(
        o.type(),
        o.pose(),
        o.description(),
        o.iconName(),
        name,
        o.hasFromTo(),
        o.fromPose(),
        o.toPose());
  }

  /** The object with another heading; an area turns about its centre. */
  public static ArMapObject withHeading(ArMapObject o, double th) {
    if (!o.isAreaType()) {
      return with(o, o.pose().withTh(th), o.fromPose(), o.toPose());
    }
    double[] c = center(o);
    double[] size = areaSize(o);
    double r = Math.toRadians(th);
    double cos = Math.cos(r);
    double sin = Math.sin(r);
    // The centre in the frame rotated by th (rotate by -th).
    double ux = c[0] * cos + c[1] * sin;
    double uy = -c[0] * sin + c[1] * cos;
    return with(
        o,
        new ArPose(c[0], c[1], th),
        new ArPose(ux - size[0] / 2, uy - size[1] / 2),
        new ArPose(ux + size[0] / 2, uy + size[1] / 2));
  }

  /** The centre of an object: its pose, the middle of a line, the centre of an area. */
  public static double[] center(ArMapObject o) {
    if (!o.hasFromTo()) {
      return new double[] {o.pose().x(), o.pose().y()};
    }
    List<ArLineSegment> segs = o.getFromToSegments();
    if (o.isLineType()) {
      ArLineSegment s = segs.get(0);
      return new double[] {(s.x1() + s.x2()) / 2, (s.y1() + s.y2()) / 2};
    }
    double x = 0;
    double y = 0;
    for (ArLineSegment s : segs) {
      x += s.x1();
      y += s.y1();
    }
    return new double[] {x / 4, y / 4};
  }

  /** Width and height of an area (in its own, rotated frame), mm. */
  public static double[] areaSize(ArMapObject o) {
    return new double[] {
      Math.abs(o.toPose().x() - o.fromPose().x()), Math.abs(o.toPose().y() - o.fromPose().y())
    };
  }

  /** The 4 corners of an area in map coordinates, as x0,y0,...,x3,y3. */
  public static double[] corners(ArMapObject o) {
    List<ArLineSegment> segs = o.getFromToSegments();
    double[] c = new double[8];
    for (int i = 0; i < 4; i++) {
      c[2 * i] = segs.get(i).x1();
      c[2 * i + 1] = segs.get(i).y1();
    }
    return c;
  }

  /**
   * How far (x, y) is from the object, mm: from a point object's position, a line's segment, or an
   * area's outline (0 inside it).
   */
  public static double distance(ArMapObject o, double x, double y) {
    if (!o.hasFromTo()) {
      return Math.hypot(o.pose().x() - x, o.pose().y() - y);
    }
    if (o.isAreaType() && o.contains(x, y)) {
      return 0;
    }
    double best = Double.POSITIVE_INFINITY;
    for (ArLineSegment s : o.getFromToSegments()) {
      best = Math.min(best, segmentDistance(s, x, y));
    }
    return best;
  }

  /** Distance from (x, y) to the segment (not the infinite line), mm. */
  public static double segmentDistance(ArLineSegment s, double x, double y) {
    double dx = s.x2() - s.x1();
    double dy = s.y2() - s.y1();
    double len2 = dx * dx + dy * dy;
    double t = len2 == 0 ? 0 : ((x - s.x1()) * dx + (y - s.y1()) * dy) / len2;
    t = Math.max(0, Math.min(1, t));
    return Math.hypot(s.x1() + t * dx - x, s.y1() + t * dy - y);
  }

  /** Whether the segment lies entirely inside the map box (x0, y0)-(x1, y1). */
  public static boolean inside(ArLineSegment s, double x0, double y0, double x1, double y1) {
    return inBox(s.x1(), s.y1(), x0, y0, x1, y1) && inBox(s.x2(), s.y2(), x0, y0, x1, y1);
  }

  /** Whether the object lies entirely inside the map box (x0, y0)-(x1, y1). */
  public static boolean inside(ArMapObject o, double x0, double y0, double x1, double y1) {
    if (!o.hasFromTo()) {
      return inBox(o.pose().x(), o.pose().y(), x0, y0, x1, y1);
    }
    for (ArLineSegment s : o.getFromToSegments()) {
      if (!inside(s, x0, y0, x1, y1)) {
        return false;
      }
    }
    return true;
  }

  private static boolean inBox(double x, double y, double x0, double y0, double x1, double y1) {
    return x >= Math.min(x0, x1)
        && x <= Math.max(x0, x1)
        && y >= Math.min(y0, y1)
        && y <= Math.max(y0, y1);
  }
}
