package org.jaria.web.model;

import java.util.Arrays;
import java.util.Objects;
import org.jaria.geom.ArPose;

/**
 * One planar laser scan: where the laser was and what each beam measured.
 *
 * @param origin the laser's pose in the map frame (mm, degrees)
 * @param startDeg bearing of the first beam relative to {@code origin}, degrees
 * @param incrementDeg angle between beams, degrees
 * @param ranges each beam's range, mm (0 or less: no return)
 */
// The array is copied in and out; equals and hashCode compare its contents.
@SuppressWarnings("ArrayRecordComponent")
public record LaserFrame(ArPose origin, double startDeg, double incrementDeg, int[] ranges) {

  /** Checks and copies. */
  public LaserFrame {
    Objects.requireNonNull(origin, "origin");
    ranges = ranges.clone();
  }

  /** A copy of the ranges. */
  @Override
  public int[] ranges() {
    return ranges.clone();
  }

  /** The number of beams. */
  public int size() {
    return ranges.length;
  }

  /** The range of beam {@code k}, mm. */
  public int range(int k) {
    return ranges[k];
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof LaserFrame l
        && origin.equals(l.origin)
        && Double.compare(startDeg, l.startDeg) == 0
        && Double.compare(incrementDeg, l.incrementDeg) == 0
        && Arrays.equals(ranges, l.ranges);
  }

  @Override
  public int hashCode() {
    return Objects.hash(origin, startDeg, incrementDeg, Arrays.hashCode(ranges));
  }

  @Override
  public String toString() {
    return "LaserFrame[" + origin + ", " + startDeg + "+" + incrementDeg + " x " + size() + "]";
  }
}
