package org.jaria.arnl.mcl;

import org.jaria.geom.ArPose;

/**
 * The filter's answer: the mean pose of its strongest cluster of particles and how spread that
 * cluster is.
 *
 * @param pose mean pose of the cluster (mm, mm, degrees)
 * @param stdX standard deviation of the cluster along x, mm
 * @param stdY standard deviation along y, mm
 * @param stdTh standard deviation of the heading, degrees
 * @param clusterWeight share of the total weight in the cluster, 0..1 (near 1 when the filter has
 *     converged on one place; small while it still considers several)
 */
public record PoseEstimate(
    ArPose pose, double stdX, double stdY, double stdTh, double clusterWeight) {

  /** Whether the cluster holds most of the weight and is no wider than the given limits. */
  public boolean isConverged(double maxStdXy, double maxStdThDeg, double minClusterWeight) {
    return clusterWeight >= minClusterWeight
        && Math.max(stdX, stdY) <= maxStdXy
        && stdTh <= maxStdThDeg;
  }
}
