package org.jaria.robot;

/**
 * Corrects one odometry heading change (ARIA's encoder correction callback): a gyro replaces the
 * wheels' turn with its own. Set it with {@link ArRobot#setEncoderCorrectionCallback}; it is called
 * on the cycle thread for every SIP.
 */
@FunctionalInterface
public interface HeadingCorrection {
  /**
   * The heading change to use, degrees, given the odometry's change in x, y (mm) and heading
   * (degrees) since the last SIP, and the clock time of this SIP.
   */
  double correctedDeltaTh(double deltaX, double deltaY, double deltaTh, long timeNanos);
}
