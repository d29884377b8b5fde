package org.jaria.range;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.robot.ArRobot;

/**
 * Something that measures distances to obstacles: sonar, bumpers, IRs, a laser (ARIA's {@code
 * ArRangeDevice}). It keeps two buffers of obstacle points in global coordinates: the
 * <em>current</em> buffer (what the sensor sees now) and the <em>cumulative</em> buffer (what it
 * has seen recently, for obstacles that have moved out of view, such as beside the robot).
 *
 * <p>Queries answer "how far is the closest obstacle in this sector / box around the robot?". A
 * result of at least {@link #getMaxRange()} means nothing was seen there. Buffers are updated on
 * the robot's cycle thread and may be queried from any thread.
 */
public abstract class ArRangeDevice {

  private final String name;
  private volatile double maxRange;

  /** What the device sees now. Hold this device's monitor to use it. */
  @GuardedBy("this")
  protected final ArRangeBuffer currentBuffer;

  /** What the device has seen recently. Hold this device's monitor to use it. */
  @GuardedBy("this")
  protected final ArRangeBuffer cumulativeBuffer;

  /** The robot the device belongs to, once added with {@link ArRobot#addRangeDevice}. */
  protected volatile ArRobot robot;

  /**
   * A device.
   *
   * @param name a name unique on its robot
   * @param maxRange farthest distance the device reports, mm
   * @param currentSize capacity of the current buffer
   * @param cumulativeSize capacity of the cumulative buffer
   */
  protected ArRangeDevice(String name, double maxRange, int currentSize, int cumulativeSize) {
    this.name = name;
    this.maxRange = maxRange;
    this.currentBuffer = new ArRangeBuffer(currentSize);
    this.cumulativeBuffer = new ArRangeBuffer(cumulativeSize);
  }

  /** The device's name. */
  public String getName() {
    return name;
  }

  /** Farthest distance the device reports, mm. */
  public double getMaxRange() {
    return maxRange;
  }

  /** Sets the farthest distance the device reports, mm. */
  public void setMaxRange(double mm) {
    maxRange = mm;
  }

  /**
   * Called by {@link ArRobot#addRangeDevice}; subclasses register the task that reads their sensor
   * here (call {@code super.setRobot}).
   */
  public void setRobot(ArRobot r) {
    robot = r;
  }

  /** The robot, or null. */
  public ArRobot getRobot() {
    return robot;
  }

  private ArPose robotPose() {
    ArRobot r = robot;
    return r == null ? ArPose.ORIGIN : r.getPose();
  }

  /**
   * Distance from the robot's centre to the closest current reading in the sector from {@code
   * startAngle} counter-clockwise to {@code endAngle} (degrees, 0 ahead, 90 left); {@link
   * #getMaxRange()} if none.
   */
  public double currentReadingPolar(double startAngle, double endAngle) {
    ArRangeBuffer.Closest c = currentReadingPolarDetail(startAngle, endAngle);
    return c == null ? maxRange : c.distance();
  }

  /** The closest current reading in the sector, with its angle and position; null if none. */
  public synchronized ArRangeBuffer.Closest currentReadingPolarDetail(
      double startAngle, double endAngle) {
    return currentBuffer.getClosestPolar(startAngle, endAngle, robotPose());
  }

  /** As {@link #currentReadingPolar}, over the cumulative buffer. */
  public synchronized double cumulativeReadingPolar(double startAngle, double endAngle) {
    ArRangeBuffer.Closest c = cumulativeBuffer.getClosestPolar(startAngle, endAngle, robotPose());
    return c == null ? maxRange : c.distance();
  }

  /**
   * Distance from the robot's centre to the closest current reading inside the box with corners
   * (x1, y1) and (x2, y2) in the robot's frame (mm, x forward, y left); {@link #getMaxRange()} if
   * none.
   */
  public double currentReadingBox(double x1, double y1, double x2, double y2) {
    ArRangeBuffer.Closest c = currentReadingBoxDetail(x1, y1, x2, y2);
    return c == null ? maxRange : c.distance();
  }

  /** The closest current reading in the box, with its position; null if none. */
  public synchronized ArRangeBuffer.Closest currentReadingBoxDetail(
      double x1, double y1, double x2, double y2) {
    return currentBuffer.getClosestBox(x1, y1, x2, y2, robotPose());
  }

  /** As {@link #currentReadingBox}, over the cumulative buffer. */
  public synchronized double cumulativeReadingBox(double x1, double y1, double x2, double y2) {
    ArRangeBuffer.Closest c = cumulativeBuffer.getClosestBox(x1, y1, x2, y2, robotPose());
    return c == null ? maxRange : c.distance();
  }

  /** The current readings' points (a copy). */
  public synchronized List<ArPose> getCurrentReadings() {
    return currentBuffer.getPoints();
  }

  /** The cumulative readings' points (a copy). */
  public synchronized List<ArPose> getCumulativeReadings() {
    return cumulativeBuffer.getPoints();
  }

  /** Empties the cumulative buffer. */
  public synchronized void clearCumulativeReadings() {
    cumulativeBuffer.clear();
  }

  /** Moves both buffers by a transform (the robot does this when its pose is corrected). */
  public synchronized void applyTransform(ArTransform t) {
    currentBuffer.applyTransform(t);
    cumulativeBuffer.applyTransform(t);
  }
}
