package org.jaria.arnl.mcl;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSensorReading;

/**
 * A set of sonar readings prepared for the sensor model: each usable echo becomes a few points on
 * the arc of its range across the transducer's cone, expressed in the robot's frame at the moment
 * of the update (readings taken earlier, at other odometry poses, are moved into that frame). The
 * model then only has to transform these points by each particle's pose and look them up.
 *
 * <p>Readings at or beyond {@code maxRange} ("no echo", or too far to trust) and below {@code
 * minRange} are not used: with a cone sensor, a missing echo says little about where walls are.
 */
public final class SonarScan {

  private final int arcSamples;
  private final int count;
  private final double[] arcX;
  private final double[] arcY;
  private final double[] range;
  private final double[] originX;
  private final double[] originY;
  private final double[] axis;
  private final int ignored;
  private final double[] throughX;
  private final double[] throughY;
  private final int[] throughStart;

  /** Spacing of the points on an echo's axis that must be clear of walls, mm. */
  static final double THROUGH_STEP = 200;

  /** How close to such a point a wall must be to count as "in the way", mm. */
  static final double THROUGH_NEAR = 100;

  /** The see-through check stops this far along the axis, mm (far echoes are least certain). */
  static final double THROUGH_MAX = 4500;

  private SonarScan(
      int arcSamples,
      int count,
      double[] arcX,
      double[] arcY,
      double[] range,
      double[] originX,
      double[] originY,
      double[] axis,
      int ignored,
      double[] throughX,
      double[] throughY,
      int[] throughStart) {
    this.arcSamples = arcSamples;
    this.count = count;
    this.arcX = arcX;
    this.arcY = arcY;
    this.range = range;
    this.originX = originX;
    this.originY = originY;
    this.axis = axis;
    this.ignored = ignored;
    this.throughX = throughX;
    this.throughY = throughY;
    this.throughStart = throughStart;
  }

  /**
   * Prepares readings for an update at odometry pose {@code encoderNow}.
   *
   * @param readings the readings (each with the odometry pose it was taken at)
   * @param minRange shorter echoes are ignored, mm
   * @param maxRange echoes at or beyond this are ignored, mm
   * @param coneHalfAngle half the opening of a transducer's cone, degrees
   * @param arcSamples points per echo across the cone (1 = the axis only)
   */
  public static SonarScan prepare(
      List<ArSensorReading> readings,
      ArPose encoderNow,
      double minRange,
      double maxRange,
      double coneHalfAngle,
      int arcSamples) {
    int k = Math.max(1, arcSamples);
    int n = readings.size();
    double[] ax = new double[n * k];
    double[] ay = new double[n * k];
    double[] rg = new double[n];
    double[] ox = new double[n];
    double[] oy = new double[n];
    double[] axis = new double[n];
    int maxThrough = (int) Math.ceil(maxRange / THROUGH_STEP) + 1;
    double[] tx = new double[n * maxThrough];
    double[] ty = new double[n * maxThrough];
    int[] tStart = new int[n + 1];
    int tn = 0;
    double nowTh = Math.toRadians(encoderNow.th());
    double c = Math.cos(nowTh);
    double s = Math.sin(nowTh);
    int used = 0;
    int ignored = 0;
    for (ArSensorReading r : readings) {
      if (r.range() < minRange || r.range() >= maxRange) {
        ignored++;
        continue;
      }
      ArPose taken = r.encoderPoseTaken();
      double dx = taken.x() - encoderNow.x();
      double dy = taken.y() - encoderNow.y();
      double rx = c * dx + s * dy;
      double ry = -s * dx + c * dy;
      double rth = Math.toRadians(taken.th()) - nowTh;
      double rc = Math.cos(rth);
      double rs = Math.sin(rth);
      double sx = rx + rc * r.sensorX() - rs * r.sensorY();
      double sy = ry + rs * r.sensorX() + rc * r.sensorY();
      double heading = rth + Math.toRadians(r.sensorTh());
      ox[used] = sx;
      oy[used] = sy;
      axis[used] = heading;
      rg[used] = r.range();
      double half = Math.toRadians(coneHalfAngle);
      for (int m = 0; m < k; m++) {
        double a = k == 1 ? heading : heading - half + 2 * half * m / (k - 1);
        ax[used * k + m] = sx + r.range() * Math.cos(a);
        ay[used * k + m] = sy + r.range() * Math.sin(a);
      }
      // The echo is the nearest surface in the cone, so its axis up to (nearly) the echo must not
      // cross a wall: points every THROUGH_STEP mm along it are checked.
      tStart[used] = tn;
      double end = Math.min(r.range() - 300, THROUGH_MAX);
      for (double d = 250; d <= end; d += THROUGH_STEP) {
        tx[tn] = sx + d * Math.cos(heading);
        ty[tn] = sy + d * Math.sin(heading);
        tn++;
      }
      used++;
      tStart[used] = tn;
    }
    return new SonarScan(k, used, ax, ay, rg, ox, oy, axis, ignored, tx, ty, tStart);
  }

  /**
   * A scan of thin beams (a laser): echo {@code i} ended at ({@code endX[i]}, {@code endY[i]}) in
   * the robot's frame, from a sensor at ({@code fromX[i]}, {@code fromY[i]}) looking along {@code
   * axis[i]} radians. The arrays are kept, not copied; their first {@code count} entries are used.
   */
  static SonarScan ofBeams(
      double[] endX,
      double[] endY,
      double[] fromX,
      double[] fromY,
      double[] axis,
      double[] range,
      int count,
      int ignored) {
    return new SonarScan(
        1,
        count,
        endX,
        endY,
        range,
        fromX,
        fromY,
        axis,
        ignored,
        new double[0],
        new double[0],
        new int[count + 1]);
  }

  /** Whether every echo is a single point with no see-through points (a laser scan). */
  boolean isBeamScan() {
    return arcSamples == 1 && throughStart[count] == 0;
  }

  /** Number of usable echoes. */
  public int size() {
    return count;
  }

  /** Number of readings not used (no echo, too far, too near). */
  public int ignoredCount() {
    return ignored;
  }

  /** Points per echo. */
  int arcSamples() {
    return arcSamples;
  }

  /** Arc point x of echo i, sample m, robot frame. */
  double arcX(int i, int m) {
    return arcX[i * arcSamples + m];
  }

  /** Arc point y of echo i, sample m, robot frame. */
  double arcY(int i, int m) {
    return arcY[i * arcSamples + m];
  }

  /** The flat arc x array (echo-major). */
  double[] arcXs() {
    return arcX;
  }

  /** The flat arc y array (echo-major). */
  double[] arcYs() {
    return arcY;
  }

  /** Index of echo i's first see-through point (echo i's points end at that of i + 1). */
  int throughStart(int i) {
    return throughStart[i];
  }

  /** The flat see-through x array (echo-major). */
  double[] throughXs() {
    return throughX;
  }

  /** The flat see-through y array. */
  double[] throughYs() {
    return throughY;
  }

  /** Range of echo i, mm. */
  public double range(int i) {
    return range[i];
  }

  /** Sensor position x of echo i in the robot frame. */
  public double originX(int i) {
    return originX[i];
  }

  /** Sensor position y of echo i in the robot frame. */
  public double originY(int i) {
    return originY[i];
  }

  /** Axis direction of echo i in the robot frame, radians. */
  public double axis(int i) {
    return axis[i];
  }
}
