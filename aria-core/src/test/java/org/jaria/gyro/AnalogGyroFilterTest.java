package org.jaria.gyro;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The gyro arithmetic with synthetic samples. */
class AnalogGyroFilterTest {

  private static final double SCALER = 1.626;
  private static final long STEP = TimeUnit.MILLISECONDS.toNanos(25);

  private final AnalogGyroFilter f = new AnalogGyroFilter(SCALER);
  private long now = 1_000_000_000L;

  private void samples(int n, int reading, double vel, double rotVel) {
    for (int i = 0; i < n; i++) {
      f.addReading(reading, 40, vel, rotVel, now);
      now += STEP;
    }
  }

  private static double rate(double deviation) {
    return -deviation * 5.0 / 1023 * 300 / 2.5 * SCALER;
  }

  @Test
  void readingsAreIgnoredUntilABiasIsKnown() {
    samples(20, 480, 0, 30);
    assertFalse(f.hasBias());
    assertEquals(0, f.getHeading(), 1e-12);
  }

  @Test
  void theBiasIsTheMeanAtRestOverASecond() {
    samples(30, 512, 0, 0);
    assertFalse(f.hasBias(), "under a second");
    samples(15, 512, 0, 0);
    assertTrue(f.hasBias());
    assertEquals(512, f.getAverage(), 1e-9);
    assertEquals(0, f.getHeading(), 1e-12);
  }

  @Test
  void motionResetsTheBiasEstimateButKeepsTheLastOne() {
    samples(45, 512, 0, 0);
    samples(10, 530, 200, 0);
    samples(20, 520, 0, 0);
    assertEquals(512, f.getAverage(), 1e-9, "not yet a second at the new value");
    samples(30, 520, 0, 0);
    assertEquals(520, f.getAverage(), 1e-9);
  }

  @Test
  void ratesIntegrateIntoTheHeading() {
    samples(45, 512, 0, 0);
    samples(40, 482, 0, 25); // 30 counts below the bias: counter-clockwise
    assertEquals(40 * rate(-30) * AnalogGyroFilter.SAMPLE_PERIOD, f.getHeading(), 1e-9);
    assertTrue(f.getHeading() > 20, "about 28.6 degrees in a second");
    double before = f.getHeading();
    samples(40, 513, 0, 0);
    assertEquals(before, f.getHeading(), 1e-12, "a count of noise at rest is no rotation");
    assertEquals(40, f.getTemperature());
  }

  @Test
  void withoutSamplesTheWheelsAreTrustedAndRemembered() {
    assertEquals(1.5, f.correctedDeltaTh(10, 0, 1.5, now), 1e-12);
    assertEquals(-0.5, f.correctedDeltaTh(10, 0, -0.5, now), 1e-12);
  }

  @Test
  void fusionWeighsTheWheelsByHowMuchTheyTurnedAndDrove() {
    samples(45, 512, 0, 0);
    f.correctedDeltaTh(0, 0, 0, now); // consume the samples so far
    samples(4, 412, 0, 40); // the gyro turned about 9.5 degrees
    double gyro = f.getHeading();
    double enc = 6;
    double iv = 0.01 * 0.01 * 10 + Math.abs(gyro) * 0.001;
    double ev = Math.abs(enc) * 0.25;
    double expected = enc * iv / (iv + ev) + gyro * ev / (iv + ev);
    double got = f.correctedDeltaTh(0, 0, enc, now);
    assertEquals(expected, got, 1e-9);
    assertTrue(Math.abs(got - gyro) < 0.1, "mostly the gyro when the wheels turn");
  }

  @Test
  void aSlippingWheelIsOverruledByTheGyro() {
    samples(45, 512, 0, 0);
    f.correctedDeltaTh(0, 0, 0, now);
    samples(4, 412, 0, 40);
    double gyro = f.getHeading();
    assertTrue(gyro > 2);
    assertEquals(gyro, f.correctedDeltaTh(50, 0, 0.2, now), 1e-9);
  }

  @Test
  void deltasWithoutSamplesAreAccountedForAtTheNextSample() {
    samples(45, 512, 0, 0);
    f.correctedDeltaTh(0, 0, 0, now);
    double a = f.correctedDeltaTh(0, 0, 0.7, now);
    assertEquals(0.7, a, 1e-12);
    samples(1, 512, 0, 0);
    // Both the wheels (0.7 + 0) and the gyro (0) are combined; the 0.7 already applied comes off.
    double iv = 0.01 * 0.01 * 10;
    double ev = 0;
    double expected = 0.7 * iv / (iv + ev) - 0.7;
    assertEquals(expected, f.correctedDeltaTh(0, 0, 0, now), 1e-9);
  }

  @Test
  void inactiveFilterPassesTheWheelsThrough() {
    samples(45, 512, 0, 0);
    samples(4, 412, 0, 40);
    f.setActive(false);
    assertEquals(3.0, f.correctedDeltaTh(0, 0, 3.0, now), 1e-12);
    assertTrue(f.getHeading() > 2, "the gyro still integrates");
  }
}
