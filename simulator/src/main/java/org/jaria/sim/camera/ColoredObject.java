package org.jaria.sim.camera;

/**
 * Something a simulated camera sees in colour: an upright cylinder (a ball, a cup, a can) or box (a
 * book, a door sign) standing on the floor. Immutable; move an object by replacing it ({@link
 * ColoredObjects#move}).
 *
 * @param id the object's id in its world
 * @param name a label for people
 * @param shape cylinder or box
 * @param x centre x, mm
 * @param y centre y, mm
 * @param th box heading, degrees (ignored for cylinders)
 * @param width cylinder diameter or box length along th, mm
 * @param depth box width across th, mm (ignored for cylinders)
 * @param bottom height of its lowest point above the floor, mm
 * @param top height of its highest point, mm
 * @param rgb colour as 0xRRGGBB
 */
public record ColoredObject(
    int id,
    String name,
    Shape shape,
    double x,
    double y,
    double th,
    double width,
    double depth,
    double bottom,
    double top,
    int rgb) {

  /** The two shapes. */
  public enum Shape {
    /** An upright cylinder of diameter {@code width}. */
    CYLINDER,
    /** A box {@code width} × {@code depth}, turned by {@code th}. */
    BOX
  }

  /** Checks the dimensions. */
  public ColoredObject {
    if (width <= 0 || (shape == Shape.BOX && depth <= 0) || top <= bottom) {
      throw new IllegalArgumentException(
          "coloured object '" + name + "' needs a positive size and top above bottom");
    }
  }

  /** A ball-like cylinder standing on the floor. */
  public static ColoredObject cylinder(
      String name, double x, double y, double diameter, double height, int rgb) {
    return new ColoredObject(-1, name, Shape.CYLINDER, x, y, 0, diameter, diameter, 0, height, rgb);
  }

  /** A box standing on the floor. */
  public static ColoredObject box(
      String name,
      double x,
      double y,
      double th,
      double length,
      double width,
      double height,
      int rgb) {
    return new ColoredObject(-1, name, Shape.BOX, x, y, th, length, width, 0, height, rgb);
  }

  /** The same object elsewhere. */
  public ColoredObject at(double newX, double newY) {
    return new ColoredObject(id, name, shape, newX, newY, th, width, depth, bottom, top, rgb);
  }

  ColoredObject withId(int newId) {
    return new ColoredObject(newId, name, shape, x, y, th, width, depth, bottom, top, rgb);
  }

  /**
   * Distance along the ray from (ox, oy) in direction (dx, dy) (a unit vector) to this object's
   * outline, or NaN if the ray misses it. Also returns, in {@code normal[0..1]}, the outline's
   * outward normal at the hit (for shading).
   */
  double intersect(double ox, double oy, double dx, double dy, double[] normal) {
    if (shape == Shape.CYLINDER) {
      double r = width / 2;
      double fx = ox - x;
      double fy = oy - y;
      double b = fx * dx + fy * dy;
      double c = fx * fx + fy * fy - r * r;
      double disc = b * b - c;
      if (disc < 0) {
        return Double.NaN;
      }
      double t = -b - Math.sqrt(disc);
      if (t < 0) {
        return Double.NaN;
      }
      normal[0] = (ox + t * dx - x) / r;
      normal[1] = (oy + t * dy - y) / r;
      return t;
    }
    // Box: slab test in the box's own frame.
    double a = Math.toRadians(th);
    double cos = Math.cos(a);
    double sin = Math.sin(a);
    double lx = cos * (ox - x) + sin * (oy - y);
    double ly = -sin * (ox - x) + cos * (oy - y);
    double ldx = cos * dx + sin * dy;
    double ldy = -sin * dx + cos * dy;
    double hx = width / 2;
    double hy = depth / 2;
    double tNear = Double.NEGATIVE_INFINITY;
    double tFar = Double.POSITIVE_INFINITY;
    int axis = -1;
    double sign = 0;
    for (int k = 0; k < 2; k++) {
      double o = k == 0 ? lx : ly;
      double d = k == 0 ? ldx : ldy;
      double h = k == 0 ? hx : hy;
      if (Math.abs(d) < 1e-12) {
        if (o < -h || o > h) {
          return Double.NaN;
        }
        continue;
      }
      double t1 = (-h - o) / d;
      double t2 = (h - o) / d;
      double s = -1;
      if (t1 > t2) {
        double tmp = t1;
        t1 = t2;
        t2 = tmp;
        s = 1;
      }
      if (t1 > tNear) {
        tNear = t1;
        axis = k;
        sign = s;
      }
      tFar = Math.min(tFar, t2);
    }
    if (tNear > tFar || tNear < 0 || axis < 0) {
      return Double.NaN;
    }
    double nx = axis == 0 ? sign : 0;
    double ny = axis == 1 ? sign : 0;
    normal[0] = cos * nx - sin * ny;
    normal[1] = sin * nx + cos * ny;
    return tNear;
  }
}
