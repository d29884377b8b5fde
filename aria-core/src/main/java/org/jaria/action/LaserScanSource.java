package org.jaria.action;

/**
 * Gives the latest laser scan (for {@link ArActionTriangleDriveTo}). A laser range device
 * implements it; tests give synthetic scans with a lambda.
 */
@FunctionalInterface
public interface LaserScanSource {

  /** The latest complete scan, or null if none has arrived. Called on the robot's cycle thread. */
  LaserScan getLaserScan();
}
