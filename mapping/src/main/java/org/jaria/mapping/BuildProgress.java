package org.jaria.mapping;

import org.jaria.geom.ArPose;

/**
 * How far a map build has come, for a progress bar or a status line.
 *
 * @param scansRead scans given to the builder
 * @param scansUsed scans matched into the map (the others were taken while standing still or had
 *     too few readings)
 * @param poses poses in the pose graph
 * @param loopClosures places recognised as seen before
 * @param pose the robot's corrected pose at the latest scan (the log's frame)
 * @param fraction how much of the log was read, 0..1, or -1 if unknown (a live log)
 */
public record BuildProgress(
    long scansRead, long scansUsed, int poses, int loopClosures, ArPose pose, double fraction) {}
