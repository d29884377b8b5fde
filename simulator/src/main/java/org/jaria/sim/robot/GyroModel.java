package org.jaria.sim.robot;

import java.util.random.RandomGenerator;

/**
 * The optional rate gyro read by the controller's A/D converter (ARCOS "HasGyro 1", the client-side
 * gyro ARIA's {@code ArAnalogGyro} corrects odometry with).
 *
 * <p>Every 25 ms the controller averages the gyro into one sample of 10 bits, centred near 512;
 * counter-clockwise turning reads below the centre. ARIA converts a sample to degrees per second as
 * {@code −(sample − centre) × 5/1023 × 300/2.5 × GyroScaler}, so the simulator produces {@code
 * centre + bias − rate / (0.5865 × GyroScaler) + noise}. The bias starts at a seeded random offset
 * and drifts as a random walk; the noise is white. Rates beyond ±300°/s saturate.
 *
 * <p>Not thread-safe: used by the world thread.
 */
public final class GyroModel {

  /** Reading at rest without bias. */
  public static final int CENTER = 512;

  /** Sample period of the controller, ms. */
  public static final double SAMPLE_MS = 25;

  /** Degrees per second per count before GyroScaler (ARIA's constant 5/1023 × 300/2.5). */
  public static final double DEG_PER_COUNT = 5.0 / 1023 * 300 / 2.5;

  /** Standard deviation of the white noise of one sample, counts. */
  public static final double NOISE_COUNTS = 0.8;

  /** Standard deviation of the initial bias, counts. */
  public static final double BIAS_COUNTS = 3;

  /** Bias random walk, counts per square root of a second. */
  public static final double DRIFT_COUNTS_PER_SQRT_S = 0.1;

  private static final int MAX_SAMPLES = 64;

  private final RandomGenerator rng;
  private final double countsPerDps;
  private double bias;
  private double windowMs;
  private double windowDeg;
  private final int[] rates = new int[MAX_SAMPLES];
  private final int[] temps = new int[MAX_SAMPLES];
  private int count;
  private boolean streaming;
  private long samplesTaken;

  /** A gyro whose counts follow ARIA's conversion with {@code gyroScaler}. */
  public GyroModel(double gyroScaler, RandomGenerator rng) {
    this.rng = rng;
    this.countsPerDps = 1 / (DEG_PER_COUNT * (gyroScaler > 0 ? gyroScaler : 1));
    this.bias = rng.nextGaussian() * BIAS_COUNTS;
  }

  /** Starts or stops keeping samples for GYROpac (GYRO 1 / GYRO 0). */
  public void setStreaming(boolean on) {
    streaming = on;
    if (!on) {
      count = 0;
    }
  }

  /** Whether GYROpacs are requested. */
  public boolean isStreaming() {
    return streaming;
  }

  /** Feeds {@code dtMs} of true rotation ({@code dthDeg}); produces a sample every 25 ms. */
  public void tick(double dtMs, double dthDeg) {
    windowMs += dtMs;
    windowDeg += dthDeg;
    while (windowMs >= SAMPLE_MS) {
      double share = SAMPLE_MS / windowMs;
      double deg = windowDeg * share;
      windowDeg -= deg;
      windowMs -= SAMPLE_MS;
      double rate = deg / (SAMPLE_MS / 1000);
      bias += rng.nextGaussian() * DRIFT_COUNTS_PER_SQRT_S * Math.sqrt(SAMPLE_MS / 1000);
      double reading = CENTER + bias - rate * countsPerDps + rng.nextGaussian() * NOISE_COUNTS;
      int r = (int) Math.round(Math.max(0, Math.min(1023, reading)));
      samplesTaken++;
      if (streaming) {
        if (count == MAX_SAMPLES) {
          System.arraycopy(rates, 1, rates, 0, MAX_SAMPLES - 1);
          System.arraycopy(temps, 1, temps, 0, MAX_SAMPLES - 1);
          count--;
        }
        rates[count] = r;
        temps[count] = 128;
        count++;
      }
    }
  }

  /** Samples waiting for the next GYROpac. */
  public int pendingCount() {
    return count;
  }

  /** Rate count of pending sample {@code k}. */
  public int pendingRate(int k) {
    return rates[k];
  }

  /** Temperature byte of pending sample {@code k}. */
  public int pendingTemperature(int k) {
    return temps[k];
  }

  /** Empties the sample queue after a GYROpac. */
  public void clearPending() {
    count = 0;
  }

  /** Current bias, counts (ground truth). */
  public double getBias() {
    return bias;
  }

  /** Gyro counts per degree per second. */
  public double countsPerDegPerSec() {
    return countsPerDps;
  }

  /** Samples taken since start. */
  public long samplesTaken() {
    return samplesTaken;
  }
}
