package org.jaria.action;

import java.util.Arrays;
import org.jaria.geom.ArMath;

/**
 * Remembers which of a number of equal sectors of the circle a heading has passed through (ARIA's
 * {@code ArSectors}), so an action can notice it has turned all the way round.
 */
final class Sectors {

  private final boolean[] seen;
  private final double sectorSize;

  /** Eight sectors of 45°, ARIA's default. */
  Sectors() {
    this(8);
  }

  Sectors(int numSectors) {
    seen = new boolean[numSectors];
    sectorSize = 360.0 / numSectors;
  }

  /** Forgets every sector. */
  void clear() {
    Arrays.fill(seen, false);
  }

  /** Marks the sector holding {@code angle} (degrees). */
  void update(double angle) {
    // ARIA indexed one past the end for exactly 180°; the last sector takes it here.
    int i = (int) ((ArMath.fixAngle(angle) + 180) / sectorSize);
    seen[Math.min(i, seen.length - 1)] = true;
  }

  /** Whether every sector has been marked. */
  boolean didAll() {
    for (boolean b : seen) {
      if (!b) {
        return false;
      }
    }
    return true;
  }
}
