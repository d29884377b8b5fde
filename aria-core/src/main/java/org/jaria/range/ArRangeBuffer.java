package org.jaria.range;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;

/**
 * A bounded set of points seen by a range device, in global coordinates, with the time each was
 * seen (ARIA's {@code ArRangeBuffer}). Stored in primitive arrays; when full, the oldest point
 * makes room. Not thread-safe: {@link ArRangeDevice} guards its buffers.
 */
public final class ArRangeBuffer {

  private final double[] xs;
  private final double[] ys;
  private final long[] times;
  private int size;
  private int next;

  /** A buffer holding at most {@code capacity} points. */
  public ArRangeBuffer(int capacity) {
    if (capacity < 1) {
      throw new IllegalArgumentException("buffer capacity must be at least 1, got " + capacity);
    }
    xs = new double[capacity];
    ys = new double[capacity];
    times = new long[capacity];
  }

  /** How many points the buffer can hold. */
  public int getCapacity() {
    return xs.length;
  }

  /** How many points it holds. */
  public int size() {
    return size;
  }

  /** Removes every point. */
  public void clear() {
    size = 0;
    next = 0;
  }

  /** Adds a point, replacing the oldest when full. */
  public void addReading(double x, double y, long timeNanos) {
    if (size < xs.length) {
      xs[size] = x;
      ys[size] = y;
      times[size] = timeNanos;
      size++;
    } else {
      xs[next] = x;
      ys[next] = y;
      times[next] = timeNanos;
      next = (next + 1) % xs.length;
    }
  }

  /**
   * Adds a point unless another lies within {@code minDist} mm of it (then that one just gets the
   * new time).
   *
   * @return whether the point was added
   */
  public boolean addReadingConditional(double x, double y, long timeNanos, double minDist) {
    double min2 = minDist * minDist;
    for (int i = 0; i < size; i++) {
      double dx = xs[i] - x;
      double dy = ys[i] - y;
      if (dx * dx + dy * dy < min2) {
        times[i] = timeNanos;
        return false;
      }
    }
    addReading(x, y, timeNanos);
    return true;
  }

  /** Removes the point at {@code i} (order is not kept). */
  private void removeAt(int i) {
    size--;
    xs[i] = xs[size];
    ys[i] = ys[size];
    times[i] = times[size];
    if (next > size) {
      next = 0;
    }
  }

  /** Removes points for which {@code filter} says true; returns how many went. */
  public int removeIf(PointFilter filter) {
    int removed = 0;
    for (int i = size - 1; i >= 0; i--) {
      if (filter.test(xs[i], ys[i], times[i])) {
        removeAt(i);
        removed++;
      }
    }
    return removed;
  }

  /** Decides about one point. */
  @FunctionalInterface
  public interface PointFilter {
    /** Whether the point (x, y) seen at {@code timeNanos} passes. */
    boolean test(double x, double y, long timeNanos);
  }

  /** Moves every point by a transform. */
  public void applyTransform(ArTransform t) {
    for (int i = 0; i < size; i++) {
      double x = xs[i];
      xs[i] = t.transformX(x, ys[i]);
      ys[i] = t.transformY(x, ys[i]);
    }
  }

  /** X of point {@code i}. */
  public double x(int i) {
    return xs[i];
  }

  /** Y of point {@code i}. */
  public double y(int i) {
    return ys[i];
  }

  /** Time point {@code i} was seen. */
  public long time(int i) {
    return times[i];
  }

  /** The points as poses (a copy, for display). */
  public List<ArPose> getPoints() {
    List<ArPose> out = new ArrayList<>(size);
    for (int i = 0; i < size; i++) {
      out.add(new ArPose(xs[i], ys[i]));
    }
    return out;
  }

  /** A found reading: its distance from the robot's centre, direction, and position. */
  public record Closest(double distance, double angle, double x, double y) {}

  /**
   * The point closest to the robot among those whose direction, relative to the robot's heading,
   * lies from {@code startAngle} counter-clockwise to {@code endAngle} (degrees); null if none.
   */
  public Closest getClosestPolar(double startAngle, double endAngle, ArPose robot) {
    Closest best = null;
    double start = ArMath.fixAngle(startAngle);
    double end = ArMath.fixAngle(endAngle);
    for (int i = 0; i < size; i++) {
      double dx = xs[i] - robot.x();
      double dy = ys[i] - robot.y();
      double angle = ArMath.subAngle(Math.toDegrees(Math.atan2(dy, dx)), robot.th());
      boolean inside =
          start < end ? angle >= start && angle <= end : angle >= start || angle <= end;
      if (!inside) {
        continue;
      }
      double d = Math.hypot(dx, dy);
      if (best == null || d < best.distance()) {
        best = new Closest(d, angle, xs[i], ys[i]);
      }
    }
    return best;
  }

  /**
   * The point closest to the robot among those inside the box with corners (x1, y1) and (x2, y2) in
   * the robot's frame (x forward, y left); null if none.
   */
  public Closest getClosestBox(double x1, double y1, double x2, double y2, ArPose robot) {
    double minX = Math.min(x1, x2);
    double maxX = Math.max(x1, x2);
    double minY = Math.min(y1, y2);
    double maxY = Math.max(y1, y2);
    double r = Math.toRadians(robot.th());
    double cos = Math.cos(r);
    double sin = Math.sin(r);
    Closest best = null;
    for (int i = 0; i < size; i++) {
      double dx = xs[i] - robot.x();
      double dy = ys[i] - robot.y();
      double lx = cos * dx + sin * dy;
      double ly = -sin * dx + cos * dy;
      if (lx < minX || lx > maxX || ly < minY || ly > maxY) {
        continue;
      }
      double d = Math.hypot(lx, ly);
      if (best == null || d < best.distance()) {
        best = new Closest(d, Math.toDegrees(Math.atan2(ly, lx)), xs[i], ys[i]);
      }
    }
    return best;
  }
}
