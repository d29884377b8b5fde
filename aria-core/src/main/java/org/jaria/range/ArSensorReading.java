package org.jaria.range;

import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;

/**
 * One reading of one range sensor (a sonar transducer), with where the sensor sits on the robot and
 * where the robot was when the reading arrived (ARIA's {@code ArSensorReading}). Immutable: a new
 * reading replaces the old one.
 *
 * @param range distance from the sensor to what it saw, mm; −1 if the sensor never reported
 * @param x global x of the point seen, mm
 * @param y global y of the point seen, mm
 * @param sensorX sensor position on the robot, mm forward of the centre
 * @param sensorY sensor position on the robot, mm to the left of the centre
 * @param sensorTh direction the sensor faces on the robot, degrees (0 = forward)
 * @param poseTaken the robot's (global) pose when the reading arrived
 * @param encoderPoseTaken the robot's odometry pose when the reading arrived
 * @param counterTaken the robot's cycle counter when the reading arrived
 * @param timeTaken clock time (ns) when the reading arrived
 */
public record ArSensorReading(
    int range,
    double x,
    double y,
    double sensorX,
    double sensorY,
    double sensorTh,
    ArPose poseTaken,
    ArPose encoderPoseTaken,
    long counterTaken,
    long timeTaken) {

  /** A sensor that has not reported yet (range −1). */
  public static ArSensorReading never(double sensorX, double sensorY, double sensorTh) {
    return new ArSensorReading(
        -1, 0, 0, sensorX, sensorY, sensorTh, ArPose.ORIGIN, ArPose.ORIGIN, -1, 0);
  }

  /**
   * A new reading of this sensor: the point seen is placed in global coordinates using the robot's
   * pose.
   */
  public ArSensorReading newData(
      int newRange, ArPose robotPose, ArPose encoderPose, long counter, long timeNanos) {
    double r = Math.toRadians(sensorTh);
    double localX = sensorX + newRange * Math.cos(r);
    double localY = sensorY + newRange * Math.sin(r);
    ArTransform t = ArTransform.ofPose(robotPose);
    return new ArSensorReading(
        newRange,
        t.transformX(localX, localY),
        t.transformY(localX, localY),
        sensorX,
        sensorY,
        sensorTh,
        robotPose,
        encoderPose,
        counter,
        timeNanos);
  }

  /** Distance from the sensor to the obstacle, mm (−1 if never read). */
  public int getRange() {
    return range;
  }

  /** Global x of the point seen. */
  public double getX() {
    return x;
  }

  /** Global y of the point seen. */
  public double getY() {
    return y;
  }

  /** The point seen, as a pose (heading 0). */
  public ArPose getPose() {
    return new ArPose(x, y);
  }

  /** The sensor's heading on the robot, degrees. */
  public double getSensorTh() {
    return sensorTh;
  }

  /** The sensor's x on the robot, mm. */
  public double getSensorX() {
    return sensorX;
  }

  /** The sensor's y on the robot, mm. */
  public double getSensorY() {
    return sensorY;
  }

  /** The robot pose the reading was taken at. */
  public ArPose getPoseTaken() {
    return poseTaken;
  }

  /** The odometry pose the reading was taken at. */
  public ArPose getEncoderPoseTaken() {
    return encoderPoseTaken;
  }

  /** The cycle counter when the reading arrived. */
  public long getCounterTaken() {
    return counterTaken;
  }

  /** Whether the reading arrived during cycle {@code counter}. */
  public boolean isNew(long counter) {
    return counterTaken == counter && range >= 0;
  }

  /** The point seen in the robot's frame at the time it was taken (x forward, y left). */
  public ArPose getLocalPose() {
    double r = Math.toRadians(sensorTh);
    return new ArPose(sensorX + range * Math.cos(r), sensorY + range * Math.sin(r));
  }

  /** This reading moved by a transform (e.g. when localization corrects the pose). */
  public ArSensorReading applyTransform(ArTransform t) {
    return new ArSensorReading(
        range,
        t.transformX(x, y),
        t.transformY(x, y),
        sensorX,
        sensorY,
        sensorTh,
        t.doTransform(poseTaken),
        encoderPoseTaken,
        counterTaken,
        timeTaken);
  }
}
