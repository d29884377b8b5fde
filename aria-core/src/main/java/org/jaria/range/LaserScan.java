package org.jaria.range;

import java.util.Arrays;
import org.jaria.geom.ArPose;

/**
 * One sweep of a laser range finder: readings as (angle, range) pairs in sweep order, with the
 * global pose of the sensor when they were taken. Range data, so it lives with the range devices;
 * actions such as {@code org.jaria.action.ArActionTriangleDriveTo} and {@code
 * org.jaria.action.ArLineFinder} work on these, so they can be fed by any laser — the simulator's
 * laser packets, a real device, or a synthetic scan in a test.
 *
 * <p>Angles are degrees relative to the sensor's heading (counter-clockwise positive), ranges mm. A
 * range of 0 or less, or at least the maximum range, means "no echo" and is skipped. Immutable.
 */
public final class LaserScan {

  private final ArPose sensorPose;
  private final double[] angles;
  private final double[] ranges;
  private final double maxRange;
  private final double[] xs;
  private final double[] ys;

  /**
   * A scan.
   *
   * @param sensorPose global pose of the laser when the scan was taken
   * @param angles reading directions, degrees relative to the sensor, in sweep order
   * @param ranges reading distances, mm
   * @param maxRange ranges at or beyond this are "no echo", mm
   * @throws IllegalArgumentException if the arrays differ in length
   */
  public LaserScan(ArPose sensorPose, double[] angles, double[] ranges, double maxRange) {
    if (angles.length != ranges.length) {
      throw new IllegalArgumentException(
          "a laser scan needs one angle per range: "
              + angles.length
              + " angles, "
              + ranges.length
              + " ranges");
    }
    this.sensorPose = sensorPose;
    this.angles = angles.clone();
    this.ranges = ranges.clone();
    this.maxRange = maxRange;
    int n = 0;
    double[] px = new double[ranges.length];
    double[] py = new double[ranges.length];
    double c = Math.cos(sensorPose.getThRad());
    double s = Math.sin(sensorPose.getThRad());
    for (int i = 0; i < ranges.length; i++) {
      double r = ranges[i];
      if (!(r > 0 && r < maxRange)) {
        continue;
      }
      double a = Math.toRadians(angles[i]);
      double lx = r * Math.cos(a);
      double ly = r * Math.sin(a);
      px[n] = sensorPose.x() + c * lx - s * ly;
      py[n] = sensorPose.y() + s * lx + c * ly;
      n++;
    }
    this.xs = Arrays.copyOf(px, n);
    this.ys = Arrays.copyOf(py, n);
  }

  /**
   * A scan of evenly spaced readings from {@code startAngle} in steps of {@code increment} degrees
   * (the usual laser layout, e.g. −90 to 90 by 1).
   */
  public static LaserScan evenlySpaced(
      ArPose sensorPose, double startAngle, double increment, double[] ranges, double maxRange) {
    double[] angles = new double[ranges.length];
    for (int i = 0; i < ranges.length; i++) {
      angles[i] = startAngle + i * increment;
    }
    return new LaserScan(sensorPose, angles, ranges, maxRange);
  }

  /** Global pose of the laser when the scan was taken. */
  public ArPose getSensorPose() {
    return sensorPose;
  }

  /** Number of readings, including those without an echo. */
  public int size() {
    return ranges.length;
  }

  /** Direction of reading {@code i}, degrees relative to the sensor. */
  public double getAngle(int i) {
    return angles[i];
  }

  /** Range of reading {@code i}, mm. */
  public double getRange(int i) {
    return ranges[i];
  }

  /** Ranges at or beyond this are "no echo", mm. */
  public double getMaxRange() {
    return maxRange;
  }

  /** Number of readings with an echo, i.e. of points. */
  public int getNumPoints() {
    return xs.length;
  }

  /** Global x of point {@code i} (points with an echo only, in sweep order), mm. */
  public double getX(int i) {
    return xs[i];
  }

  /** Global y of point {@code i}, mm. */
  public double getY(int i) {
    return ys[i];
  }
}
