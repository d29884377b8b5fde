package org.jaria.web.model;

import java.util.Objects;
import org.jaria.geom.ArPose;

/**
 * One robot at one instant, as the page and Foxglove show it. Poses are in the map frame,
 * millimetres and degrees; a part that the source does not know is null (poses, laser, goal) or
 * empty (points).
 *
 * @param name the robot's name (unique in a frame)
 * @param model its model ("p3dx-sh")
 * @param truePose where it really is (the simulator's truth), or null for a real robot
 * @param believedPose where it believes it is (localization or odometry), or null
 * @param footprint its outline at the true pose (else at the believed pose), corners in order
 * @param sonarOrigins where each sonar that got an echo sits
 * @param sonarEchoes where each of those echoes came from (same order as {@code sonarOrigins})
 * @param laser the last laser scan, or null
 * @param particles the localization's particles (x, y), empty without localization
 * @param path the planned path's points, empty without a plan
 * @param goal the goal being driven to, or null
 * @param status speeds, battery, mode
 */
public record RobotFrame(
    String name,
    String model,
    ArPose truePose,
    ArPose believedPose,
    Points footprint,
    Points sonarOrigins,
    Points sonarEchoes,
    LaserFrame laser,
    Points particles,
    Points path,
    ArPose goal,
    RobotStatus status) {

  /** Checks. */
  public RobotFrame {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(model, "model");
    Objects.requireNonNull(footprint, "footprint");
    Objects.requireNonNull(sonarOrigins, "sonarOrigins");
    Objects.requireNonNull(sonarEchoes, "sonarEchoes");
    Objects.requireNonNull(particles, "particles");
    Objects.requireNonNull(path, "path");
    Objects.requireNonNull(status, "status");
    if (sonarOrigins.size() != sonarEchoes.size()) {
      throw new IllegalArgumentException(
          sonarOrigins.size() + " sonar origins but " + sonarEchoes.size() + " echoes");
    }
  }

  /** The pose to draw the robot at: the true one if known, else the believed one. */
  public ArPose shownPose() {
    return truePose != null ? truePose : believedPose;
  }

  /** This frame with what a localization adds (believed pose, particles, path, goal, status). */
  public RobotFrame withNavigation(
      ArPose believed, Points newParticles, Points newPath, ArPose newGoal, RobotStatus s) {
    return new RobotFrame(
        name,
        model,
        truePose,
        believed,
        footprint,
        sonarOrigins,
        sonarEchoes,
        laser,
        newParticles,
        newPath,
        newGoal,
        s);
  }
}
