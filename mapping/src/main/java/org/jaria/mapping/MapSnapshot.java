package org.jaria.mapping;

import org.jaria.geom.ArPose;

/**
 * The map while it is being built, for drawing it live: the points seen so far (one per 50 mm cell,
 * placed by the current pose estimates) and the path driven. Arrays are the snapshot's own; a newer
 * snapshot does not change them.
 *
 * @param xs points' x, mm
 * @param ys points' y, mm
 * @param pathX the poses' x in order, mm
 * @param pathY the poses' y, mm
 * @param pose the latest pose
 */
public record MapSnapshot(int[] xs, int[] ys, double[] pathX, double[] pathY, ArPose pose) {

  /** Number of points. */
  public int size() {
    return xs.length;
  }
}
