package org.jaria.mapping;

import org.jaria.laser.log.LoggedScan;

/**
 * Recognises readings at a laser's "no echo" range. A laser that saw nothing reports its maximum
 * range (a simulator may too), and a logger that does not know that writes a phantom point there;
 * such points draw a false circle of walls around every scan. A real wall almost never gives five
 * readings of one sweep at the very same farthest range, so when at least {@link #MIN_SAME}
 * readings lie within {@link #TOLERANCE_MM} of the sweep's farthest one, that range is taken as the
 * laser's no-echo range, and from then on every reading at or beyond it is dropped.
 *
 * <p>Not thread-safe: one per log.
 */
final class NoEchoFilter {

  /**
   * Readings this close to the farthest count as "the same range", mm: the log rounds x and y to
   * the millimetre, which moves a range by up to 0.7 mm.
   */
  static final double TOLERANCE_MM = 1.5;

  /**
   * This many readings at the farthest range reveal a no-echo range. A flat wall cannot do that
   * beyond 3 m: five beams 1 degree apart span 4 degrees, and the outer ones reach a wall 3 m away
   * (beyond {@link #MIN_NO_ECHO_MM}) 7 mm farther than the middle one.
   */
  static final int MIN_SAME = 5;

  /** Below this range a cluster of equal readings is a real object, not a no-echo value, mm. */
  static final double MIN_NO_ECHO_MM = 3000;

  private double noEcho = Double.POSITIVE_INFINITY;
  private long dropped;

  /** Learns from a scan; call before {@link #isNoEcho} for its readings. */
  void learn(LoggedScan s) {
    double max = 0;
    for (int i = 0; i < s.size(); i++) {
      if (s.hasEcho(i)) {
        max = Math.max(max, s.range(i));
      }
    }
    if (max < MIN_NO_ECHO_MM || max >= noEcho) {
      return;
    }
    int same = 0;
    for (int i = 0; i < s.size(); i++) {
      if (s.hasEcho(i) && s.range(i) >= max - TOLERANCE_MM) {
        same++;
      }
    }
    if (same >= MIN_SAME) {
      noEcho = max - TOLERANCE_MM;
    }
  }

  /** Whether a reading at {@code range} mm is a no-echo reading (counted). */
  boolean isNoEcho(double range) {
    if (range >= noEcho) {
      dropped++;
      return true;
    }
    return false;
  }

  /** The no-echo range found, or infinity if none. */
  double noEchoRange() {
    return noEcho;
  }

  /** Readings dropped as no-echo. */
  long dropped() {
    return dropped;
  }
}
