package org.jaria.range;

/**
 * Gives the latest laser scan (for actions such as {@code
 * org.jaria.action.ArActionTriangleDriveTo}; the range package does not know its users). A laser
 * range device implements it; tests give synthetic scans with a lambda.
 */
@FunctionalInterface
public interface LaserScanSource {

  /** The latest complete scan, or null if none has arrived. Called on the robot's cycle thread. */
  LaserScan getLaserScan();
}
