package org.jaria.arnl.plan;

import java.util.Arrays;

/**
 * A small rolling occupancy grid of what the sonar has seen around the robot, the classic way to
 * make sense of wide-cone sonar: an echo at range r says that something is somewhere on the arc at
 * r across the cone, and that the cone in front of that arc is empty. Each reading raises the
 * evidence (log-odds) of the arc's cells and lowers that of the cells before it, so that an echo
 * placed wrongly at the edge of one cone (beside a doorway, past the corner of a box) is cleared by
 * the other readings that see through that spot, and a narrow passage opens up again.
 *
 * <p>The evidence an echo adds to an arc cell falls off with the cell's angle from the cone's axis
 * (a Gaussian of half the cone's half-width) and with its range (a far arc is wide), so one far
 * echo or one at the edge of a cone is not yet an obstacle, while an object that several cones see,
 * or that lies near one's axis, is.
 *
 * <p>The grid lives in odometry coordinates, which never jump, and follows the robot (it moves by
 * whole cells when the robot nears its edge). Not thread-safe.
 */
public final class SonarOccupancy {

  private static final float OCCUPIED = 0.85f;
  private static final float FREE = 0.5f;
  private static final float FREE_NO_ECHO = 0.15f;
  private static final float LIMIT = 2f;

  private final double res;
  private final int n;
  private float[] logOdds;
  private double originX;
  private double originY;
  private boolean placed;

  /** A grid {@code size} mm across with cells of {@code res} mm. */
  public SonarOccupancy(double size, double res) {
    if (!(res > 0) || !(size >= 10 * res)) {
      throw new IllegalArgumentException(
          "sonar grid needs res > 0 and size >= 10 cells, got " + size + ", " + res);
    }
    this.res = res;
    this.n = (int) Math.ceil(size / res);
    this.logOdds = new float[n * n];
  }

  /** Forgets everything. */
  public void clear() {
    Arrays.fill(logOdds, 0);
  }

  /** Keeps (x, y) (odometry mm) in the middle half of the grid, shifting it if needed. */
  public void follow(double x, double y) {
    double half = n * res / 2;
    if (!placed) {
      originX = Math.floor((x - half) / res) * res;
      originY = Math.floor((y - half) / res) * res;
      placed = true;
      return;
    }
    double cx = originX + half;
    double cy = originY + half;
    if (Math.abs(x - cx) < half / 2 && Math.abs(y - cy) < half / 2) {
      return;
    }
    int di = (int) Math.round((x - cx) / res);
    int dj = (int) Math.round((y - cy) / res);
    float[] moved = new float[n * n];
    for (int j = 0; j < n; j++) {
      int oj = j + dj;
      if (oj < 0 || oj >= n) {
        continue;
      }
      for (int i = 0; i < n; i++) {
        int oi = i + di;
        if (oi >= 0 && oi < n) {
          moved[j * n + i] = logOdds[oj * n + oi];
        }
      }
    }
    logOdds = moved;
    originX += di * res;
    originY += dj * res;
  }

  /**
   * Adds one reading.
   *
   * @param sx sensor x (odometry mm)
   * @param sy sensor y
   * @param axis direction the sensor faces (odometry frame), radians
   * @param range the reading, mm
   * @param maxRange readings at or beyond this are "no echo": only the near part of the cone is
   *     cleared, weakly (a surface at a grazing angle may be there unseen)
   * @param coneHalf half the cone's opening, radians
   */
  public void addReading(
      double sx, double sy, double axis, double range, double maxRange, double coneHalf) {
    addReading(sx, sy, axis, range, maxRange, coneHalf, false);
  }

  /**
   * As {@link #addReading(double, double, double, double, double, double)}; an {@code explained}
   * echo (the map says a wall is at that range in the cone) only clears the cone in front of it:
   * the wall is known exactly, and placing its echo across the cone would put phantom obstacles
   * beside it — across a doorway when the echo came from the door frame.
   */
  public void addReading(
      double sx,
      double sy,
      double axis,
      double range,
      double maxRange,
      double coneHalf,
      boolean explained) {
    if (!placed || range <= 0) {
      return;
    }
    boolean echo = range < maxRange;
    double eps = res;
    double reach = echo ? range + eps : Math.min(maxRange, 2000);
    double ax = Math.cos(axis);
    double ay = Math.sin(axis);
    double cosHalf = Math.cos(echo ? coneHalf : coneHalf / 3);
    double spread = Math.max(1e-3, coneHalf / 2);
    double inv2 = 1 / (2 * spread * spread);
    // A far echo's arc is wide, so it says less about any one cell.
    double rangeWeight = Math.max(0.3, Math.min(1, 1.2 - range / 2500));
    int i0 = Math.max(0, (int) Math.floor((sx - reach - originX) / res));
    int i1 = Math.min(n - 1, (int) Math.floor((sx + reach - originX) / res));
    int j0 = Math.max(0, (int) Math.floor((sy - reach - originY) / res));
    int j1 = Math.min(n - 1, (int) Math.floor((sy + reach - originY) / res));
    for (int j = j0; j <= j1; j++) {
      double dy = originY + (j + 0.5) * res - sy;
      for (int i = i0; i <= i1; i++) {
        double dx = originX + (i + 0.5) * res - sx;
        double d = Math.sqrt(dx * dx + dy * dy);
        if (d > reach || d < 1 || (dx * ax + dy * ay) < cosHalf * d) {
          continue;
        }
        int k = j * n + i;
        float v = logOdds[k];
        if (echo && Math.abs(d - range) <= eps) {
          if (explained) {
            continue;
          }
          double cross = dx * ay - dy * ax;
          double along = dx * ax + dy * ay;
          double a = Math.atan2(Math.abs(cross), along);
          v += (float) (OCCUPIED * rangeWeight * Math.exp(-a * a * inv2));
        } else if (d < range - eps) {
          v -= echo ? FREE : FREE_NO_ECHO;
        } else {
          continue;
        }
        logOdds[k] = Math.max(-LIMIT, Math.min(LIMIT, v));
      }
    }
  }

  /** Log-odds of occupancy at (x, y) (odometry mm); 0 (unknown) outside the grid. */
  public float logOddsAt(double x, double y) {
    int i = (int) Math.floor((x - originX) / res);
    int j = (int) Math.floor((y - originY) / res);
    return i < 0 || j < 0 || i >= n || j >= n ? 0 : logOdds[j * n + i];
  }

  /** Receives occupied cells. */
  @FunctionalInterface
  public interface CellSink {
    /** An occupied cell's centre (odometry mm). */
    void accept(double x, double y);
  }

  /**
   * Calls {@code sink} with the centre of every cell within {@code radius} of (x, y) whose log-odds
   * exceed {@code threshold}.
   */
  public void occupiedNear(double x, double y, double radius, double threshold, CellSink sink) {
    int r = (int) Math.ceil(radius / res);
    int ci = (int) Math.floor((x - originX) / res);
    int cj = (int) Math.floor((y - originY) / res);
    double r2 = radius * radius;
    for (int j = Math.max(0, cj - r); j <= Math.min(n - 1, cj + r); j++) {
      double py = originY + (j + 0.5) * res;
      for (int i = Math.max(0, ci - r); i <= Math.min(n - 1, ci + r); i++) {
        if (logOdds[j * n + i] <= threshold) {
          continue;
        }
        double px = originX + (i + 0.5) * res;
        if ((px - x) * (px - x) + (py - y) * (py - y) <= r2) {
          sink.accept(px, py);
        }
      }
    }
  }

  /** Cell size, mm. */
  public double resolution() {
    return res;
  }
}
