package org.jaria.sim.world;

import java.util.List;
import org.jaria.geom.ArPose;

/**
 * A robot's outline on the floor: the rectangle from {@code RobotLengthRear} behind the centre of
 * rotation to {@code RobotLengthFront} ahead of it, {@code RobotWidth} wide. {@link #place} moves
 * it to a pose; the corners are kept in arrays (counter-clockwise) so collision and ray tests
 * allocate nothing.
 */
public final class Footprint {

  private final double front;
  private final double rear;
  private final double halfWidth;
  private final double radius;

  /** Corner x coordinates, world frame, counter-clockwise. */
  final double[] x = new double[4];

  /** Corner y coordinates, world frame, counter-clockwise. */
  final double[] y = new double[4];

  private double cx;
  private double cy;

  /**
   * A footprint of the given dimensions, mm.
   *
   * @param front distance from the centre of rotation to the front
   * @param rear distance from the centre of rotation to the back
   * @param width total width
   */
  public Footprint(double front, double rear, double width) {
    if (!(front > 0 && rear > 0 && width > 0)) {
      throw new IllegalArgumentException(
          "robot dimensions must be positive: front "
              + front
              + ", rear "
              + rear
              + ", width "
              + width);
    }
    this.front = front;
    this.rear = rear;
    this.halfWidth = width / 2;
    this.radius = Math.hypot(Math.max(front, rear), halfWidth);
  }

  /** A footprint with the same dimensions, placed independently. */
  public Footprint copy() {
    Footprint f = new Footprint(front, rear, 2 * halfWidth);
    f.copyFrom(this);
    return f;
  }

  /** Takes the placement of {@code other} (which must have the same dimensions). */
  public void copyFrom(Footprint other) {
    System.arraycopy(other.x, 0, x, 0, 4);
    System.arraycopy(other.y, 0, y, 0, 4);
    cx = other.cx;
    cy = other.cy;
  }

  /** Moves the footprint so that its centre of rotation is at (px, py) facing {@code thRad}. */
  public void place(double px, double py, double thRad) {
    double c = Math.cos(thRad);
    double s = Math.sin(thRad);
    set(0, px, py, c, s, front, -halfWidth);
    set(1, px, py, c, s, front, halfWidth);
    set(2, px, py, c, s, -rear, halfWidth);
    set(3, px, py, c, s, -rear, -halfWidth);
    cx = px;
    cy = py;
  }

  private void set(int i, double px, double py, double c, double s, double lx, double ly) {
    x[i] = px + c * lx - s * ly;
    y[i] = py + s * lx + c * ly;
  }

  /** Centre of rotation x, mm. */
  public double centerX() {
    return cx;
  }

  /** Centre of rotation y, mm. */
  public double centerY() {
    return cy;
  }

  /** Radius of the circle around the centre of rotation that contains the footprint, mm. */
  public double boundingRadius() {
    return radius;
  }

  /** Distance from the centre of rotation to the front, mm. */
  public double front() {
    return front;
  }

  /** Distance from the centre of rotation to the back, mm. */
  public double rear() {
    return rear;
  }

  /** Total width, mm. */
  public double width() {
    return 2 * halfWidth;
  }

  /** The four corners (front right, front left, rear left, rear right), world frame. */
  public List<ArPose> corners() {
    return List.of(
        new ArPose(x[0], y[0]),
        new ArPose(x[1], y[1]),
        new ArPose(x[2], y[2]),
        new ArPose(x[3], y[3]));
  }

  /** Whether the point (px, py) is inside the placed footprint. */
  public boolean contains(double px, double py) {
    return Geometry2d.pointInConvex(px, py, x, y, 4);
  }

  /** Whether this placed footprint overlaps {@code other}. */
  public boolean overlaps(Footprint other) {
    double ddx = other.cx - cx;
    double ddy = other.cy - cy;
    double r = radius + other.radius;
    if (ddx * ddx + ddy * ddy > r * r) {
      return false;
    }
    return Geometry2d.convexOverlap(x, y, 4, other.x, other.y, 4);
  }

  /**
   * Offers the contact between this footprint and the overlapping {@code other} to {@code out}: the
   * length-weighted middle of the parts of this footprint's edges inside {@code other} and of
   * {@code other}'s edges inside this one.
   */
  void offerContact(Footprint other, Contact out, int robotIndex) {
    double[] t = new double[2];
    double sx = 0;
    double sy = 0;
    double total = 0;
    double lastX = other.cx;
    double lastY = other.cy;
    for (int pass = 0; pass < 2; pass++) {
      Footprint edges = pass == 0 ? this : other;
      Footprint area = pass == 0 ? other : this;
      for (int i = 0, j = 3; i < 4; j = i++) {
        if (Geometry2d.clipSegmentConvex(
            edges.x[j], edges.y[j], edges.x[i], edges.y[i], area.x, area.y, 4, t)) {
          double mt = (t[0] + t[1]) / 2;
          double mx = edges.x[j] + mt * (edges.x[i] - edges.x[j]);
          double my = edges.y[j] + mt * (edges.y[i] - edges.y[j]);
          double len = (t[1] - t[0]) * Math.hypot(edges.x[i] - edges.x[j], edges.y[i] - edges.y[j]);
          sx += mx * len;
          sy += my * len;
          total += len;
          lastX = mx;
          lastY = my;
        }
      }
    }
    double px = total > 1e-9 ? sx / total : lastX;
    double py = total > 1e-9 ? sy / total : lastY;
    out.offer(px, py, other.cx, other.cy, RayHit.HitKind.ROBOT, robotIndex);
  }

  /**
   * Distance along a ray to this footprint, 0 if the origin is inside, {@link
   * Double#POSITIVE_INFINITY} if the ray misses; writes the incidence cosine into {@code hit} only
   * when the distance is nearer than {@code hit.distance}.
   */
  double cast(double ox, double oy, double dx, double dy, RayHit hit, int robotIndex) {
    double mx = cx - ox;
    double my = cy - oy;
    double along = mx * dx + my * dy;
    double perp2 = mx * mx + my * my - along * along;
    if (perp2 > radius * radius || along + radius < 0 || along - radius > hit.distance) {
      return Double.POSITIVE_INFINITY;
    }
    if (contains(ox, oy)) {
      hit.distance = 0;
      hit.cosIncidence = 1;
      hit.kind = RayHit.HitKind.ROBOT;
      hit.robot = robotIndex;
      return 0;
    }
    double best = Double.POSITIVE_INFINITY;
    int edge = -1;
    for (int i = 0, j = 3; i < 4; j = i++) {
      double t = Geometry2d.raySegment(ox, oy, dx, dy, x[j], y[j], x[i], y[i]);
      if (t < best) {
        best = t;
        edge = j;
      }
    }
    if (edge >= 0 && best < hit.distance) {
      int next = (edge + 1) % 4;
      hit.distance = best;
      hit.cosIncidence = Geometry2d.cosIncidenceSegment(dx, dy, x[edge], y[edge], x[next], y[next]);
      hit.kind = RayHit.HitKind.ROBOT;
      hit.robot = robotIndex;
    }
    return best;
  }
}
