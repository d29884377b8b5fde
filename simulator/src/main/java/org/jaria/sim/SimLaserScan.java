package org.jaria.sim;

import java.util.Arrays;
import org.jaria.geom.ArPose;

/**
 * One simulated laser scan: reading {@code k} is at {@code startDeg + k × incrementDeg} from the
 * laser's heading.
 *
 * @param origin the laser's world pose when it scanned
 * @param startDeg angle of the first reading relative to the laser, degrees
 * @param incrementDeg angle between readings, degrees
 * @param ranges ranges, mm (the maximum range where nothing was hit)
 */
// The array is copied in and out.
@SuppressWarnings("ArrayRecordComponent")
public record SimLaserScan(ArPose origin, double startDeg, double incrementDeg, int[] ranges) {

  /** Copies the ranges. */
  public SimLaserScan {
    ranges = ranges.clone();
  }

  @Override
  public int[] ranges() {
    return ranges.clone();
  }

  /** Number of readings. */
  public int size() {
    return ranges.length;
  }

  /** Range of reading {@code k}, mm. */
  public int range(int k) {
    return ranges[k];
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof SimLaserScan s
        && s.origin.equals(origin)
        && s.startDeg == startDeg
        && s.incrementDeg == incrementDeg
        && Arrays.equals(s.ranges, ranges);
  }

  @Override
  public int hashCode() {
    return 31 * origin.hashCode() + Arrays.hashCode(ranges);
  }

  @Override
  public String toString() {
    return "SimLaserScan[" + origin + ", " + ranges.length + " readings from " + startDeg + "°]";
  }
}
