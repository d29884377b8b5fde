package org.jaria.sim;

/**
 * Ground truth of the last firing of one sonar transducer: what the sensor really saw, next to what
 * it reported.
 *
 * @param index transducer number (0-based, as in the SIP)
 * @param fireCount how many times it has fired (0: never, the other fields are meaningless)
 * @param trueRangeMm distance to the nearest echoing surface in its cone before noise, or NaN for
 *     no echo
 * @param reportedRangeMm the range sent to the client, mm (5000 for no echo)
 * @param hitX world x of the echo point (valid when {@code trueRangeMm} is a number)
 * @param hitY world y of the echo point
 * @param sensorX world x of the transducer now
 * @param sensorY world y of the transducer now
 * @param sensorThDeg world heading of the transducer now, degrees
 */
public record SonarTruth(
    int index,
    long fireCount,
    double trueRangeMm,
    int reportedRangeMm,
    double hitX,
    double hitY,
    double sensorX,
    double sensorY,
    double sensorThDeg) {

  /** Whether the last firing got an echo. */
  public boolean hasEcho() {
    return !Double.isNaN(trueRangeMm);
  }
}
