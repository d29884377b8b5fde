package org.jaria.gyro;

import java.util.concurrent.TimeUnit;
import org.jaria.geom.ArMath;

/**
 * The arithmetic of ARIA's client-side gyro correction ({@code ArAnalogGyro}), separate from any
 * robot so it can be tested with synthetic readings.
 *
 * <p><b>Rates.</b> Each GYROpac sample is a 10-bit reading of the gyro's rate output, taken every
 * 25 ms. While the robot stands still (under 1 mm/s and 1 deg/s) and the readings stay within 0.5 %
 * of their running mean, that mean becomes the gyro's bias once it has lasted a second over more
 * than 25 samples. Until a bias is known, readings are ignored. A reading minus the bias converts
 * to a rate as {@code rate = −(reading − bias) × 5 / 1023 × 300 / 2.5 × GyroScaler} deg/s (the gyro
 * gives 2.5 V at 300 deg/s; {@code GyroScaler} comes from the robot's parameter file), so a reading
 * above the bias means turning clockwise. Tiny deviations (under 2 counts) while standing still
 * count as no rotation. Rates are integrated into {@link #getHeading()}.
 *
 * <p><b>Fusion.</b> Each odometry update gives the wheels' change of heading; {@link
 * #correctedDeltaTh} returns the change to use instead: a variance-weighted mean of the wheels' and
 * the gyro's changes, where the wheels are trusted less the more the robot turns and drives, and
 * the gyro less the more it turns. If the wheels say "no turn" (under 1°) but the gyro turned more
 * than 2°, the gyro wins outright (a wheel slipping on the spot). Odometry updates without gyro
 * samples in between are passed through and accounted for at the next one.
 *
 * <p>Thread-safe: samples and odometry may come from different threads.
 */
public final class AnalogGyroFilter {

  /** Seconds each sample represents (the gyro is sampled at 40 Hz). */
  public static final double SAMPLE_PERIOD = .025;

  private static final double GYRO_SIGMA = .01;
  private static final double INERTIAL_VARIANCE_MODEL = .001;
  private static final double ROT_VARIANCE_MODEL = .25;
  private static final double TRANS_VARIANCE_MODEL = 4.0;

  private double scalingFactor;
  private double heading;
  private double lastHeading;
  private boolean readingThisCycle;
  private double accumulatedDelta;
  private double averageTotal;
  private int averageCount;
  private boolean averageStarted;
  private long averageStartedNanos;
  private double lastAverage;
  private long lastAverageTakenNanos;
  private int temperature;
  private boolean active = true;
  private long samples;

  /** A filter with {@code scalingFactor} ({@code GyroScaler} from the robot's parameters). */
  public AnalogGyroFilter(double scalingFactor) {
    this.scalingFactor = scalingFactor;
  }

  /** Sets the scale of the rate readings ({@code GyroScaler}). */
  public synchronized void setScalingFactor(double scalingFactor) {
    this.scalingFactor = scalingFactor;
  }

  /** The scale of the rate readings. */
  public synchronized double getScalingFactor() {
    return scalingFactor;
  }

  /**
   * Takes one gyro sample.
   *
   * @param reading the rate reading, 0..1023
   * @param temperatureReading the gyro's temperature byte
   * @param robotVel the robot's translational velocity now, mm/s
   * @param robotRotVel the robot's rotational velocity now, deg/s
   * @param nowNanos clock time, ns
   */
  public synchronized void addReading(
      int reading, int temperatureReading, double robotVel, double robotRotVel, long nowNanos) {
    if (!averageStarted) {
      averageStarted = true;
      averageStartedNanos = nowNanos;
    }
    boolean still = Math.abs(robotVel) < 1 && Math.abs(robotRotVel) < 1;
    if (still
        && (averageCount == 0
            || Math.abs(averageTotal / averageCount - reading)
                < averageTotal / averageCount * .005)) {
      if (nowNanos - averageStartedNanos > TimeUnit.SECONDS.toNanos(1) && averageCount > 25) {
        lastAverage = averageTotal / averageCount;
        lastAverageTakenNanos = nowNanos;
        averageTotal = 0;
        averageCount = 0;
        averageStartedNanos = nowNanos;
      }
      averageTotal += reading;
      averageCount++;
    } else {
      averageTotal = 0;
      averageCount = 0;
      averageStartedNanos = nowNanos;
    }
    samples++;
    if (lastAverage == 0) {
      return;
    }
    double deviation = reading - lastAverage;
    double rate = -(deviation * 5.0 / 1023) * 300 / 2.5 * scalingFactor;
    temperature = temperatureReading;
    if (Math.abs(robotVel) < 2 && Math.abs(robotRotVel) < 2 && Math.abs(deviation) < 2) {
      rate = 0;
    }
    heading = ArMath.fixAngle(heading + rate * SAMPLE_PERIOD);
    readingThisCycle = true;
  }

  /**
   * The change of heading to use for one odometry update (the signature of the robot's heading
   * correction hook).
   *
   * @param deltaX the update's change of x, mm
   * @param deltaY the update's change of y, mm
   * @param deltaTh the wheels' change of heading, degrees
   * @param timeNanos when the update arrived (unused; kept for the hook's signature)
   * @return the corrected change of heading, degrees
   */
  public synchronized double correctedDeltaTh(
      double deltaX, double deltaY, double deltaTh, long timeNanos) {
    if (!readingThisCycle) {
      accumulatedDelta += deltaTh;
      return deltaTh;
    }
    double robotDeltaTh = ArMath.fixAngle(accumulatedDelta + deltaTh);
    double inertialDeltaTh = ArMath.subAngle(heading, lastHeading);
    double inertialVariance =
        GYRO_SIGMA * GYRO_SIGMA * 10 + Math.abs(inertialDeltaTh) * INERTIAL_VARIANCE_MODEL;
    double encoderVariance =
        Math.abs(deltaTh) * ROT_VARIANCE_MODEL + Math.hypot(deltaX, deltaY) * TRANS_VARIANCE_MODEL;
    double sum = inertialVariance + encoderVariance;
    double result;
    if (Math.abs(sum) < .00000001) {
      result = 0;
    } else if (Math.abs(robotDeltaTh) < 1 && Math.abs(inertialDeltaTh) > 2) {
      result = ArMath.fixAngle(inertialDeltaTh);
    } else {
      result =
          ArMath.fixAngle(
              robotDeltaTh * (inertialVariance / sum) + inertialDeltaTh * (encoderVariance / sum));
    }
    result -= accumulatedDelta;
    readingThisCycle = false;
    lastHeading = heading;
    accumulatedDelta = 0;
    return active ? result : deltaTh;
  }

  /** The heading integrated from the gyro alone, degrees. */
  public synchronized double getHeading() {
    return heading;
  }

  /** The gyro's bias (mean reading at rest), 0 until one is known. */
  public synchronized double getAverage() {
    return lastAverage;
  }

  /** When the bias was last taken, clock ns (0 if never). */
  public synchronized long getAverageTakenNanos() {
    return lastAverageTakenNanos;
  }

  /** Whether a bias is known, so readings are being integrated. */
  public synchronized boolean hasBias() {
    return lastAverage != 0;
  }

  /** The last temperature byte. */
  public synchronized int getTemperature() {
    return temperature;
  }

  /** Samples taken so far. */
  public synchronized long getSampleCount() {
    return samples;
  }

  /** Whether corrections are applied ({@link #correctedDeltaTh} passes odometry through if not). */
  public synchronized boolean isActive() {
    return active;
  }

  /** Switches corrections on or off; the gyro keeps integrating either way. */
  public synchronized void setActive(boolean active) {
    this.active = active;
  }
}
