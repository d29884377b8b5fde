package org.jaria.laser;

/**
 * How a Hokuyo URG is read (ARIA's {@code -laserStartDegrees}, {@code -laserEndDegrees}, {@code
 * -laserIncrement} and baud choices for the URG).
 *
 * @param startDeg first reading's angle, degrees (negative: right of the front)
 * @param endDeg last reading's angle, degrees
 * @param clusterCount how many neighbouring steps make one reading (1: every step, about 0.35°)
 * @param startingBaud the serial rate the URG talks at now (19200 after power-up)
 * @param baud the serial rate to switch to after connecting (ignored on USB and TCP)
 */
public record UrgSettings(
    double startDeg, double endDeg, int clusterCount, int startingBaud, int baud) {

  /** −90° to 90° at every step, 19200 baud. */
  public static final UrgSettings DEFAULT = new UrgSettings(-90, 90, 1, 19200, 19200);

  /** Checks. */
  public UrgSettings {
    if (!(startDeg < endDeg) || startDeg < -180 || endDeg > 180) {
      throw new IllegalArgumentException(
          "URG field " + startDeg + ".." + endDeg + " must run upwards within -180..180 degrees");
    }
    if (clusterCount < 1 || clusterCount > 99) {
      throw new IllegalArgumentException("URG cluster count is 1..99, not " + clusterCount);
    }
    for (int b : new int[] {startingBaud, baud}) {
      if (b != 19200
          && b != 38400
          && b != 57600
          && b != 115200
          && b != 250000
          && b != 500000
          && b != 750000) {
        throw new IllegalArgumentException("a URG does not talk at " + b + " baud");
      }
    }
  }
}
