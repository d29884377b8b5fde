package org.jaria.sim;

import java.util.List;
import org.jaria.geom.ArPose;

/**
 * A consistent, immutable picture of a world at one instant, for drawing and inspection from any
 * thread (the GUI's view of the simulator).
 *
 * @param simTimeNanos simulated time of the picture
 * @param robots every robot, in the order they were added
 * @param obstacles every injected obstacle
 */
public record SimSnapshot(long simTimeNanos, List<RobotView> robots, List<SimObstacle> obstacles) {

  /** Copies the lists. */
  public SimSnapshot {
    robots = List.copyOf(robots);
    obstacles = List.copyOf(obstacles);
  }

  /**
   * One robot in a {@link SimSnapshot}.
   *
   * @param index its number in the world
   * @param name its name
   * @param subtype its model
   * @param truePose where it really is
   * @param odometryPose where its odometry says it is
   * @param footprint its outline, world frame (front right, front left, rear left, rear right)
   * @param sonar the last reading of every transducer
   * @param laser the last laser scan, or null
   * @param stallAndBumpers stall and bumper bits as in the SIP
   * @param vel translational velocity, mm/s
   * @param rotVel rotational velocity, deg/s
   * @param motorsEnabled whether the motors are enabled
   * @param clientConnected whether a client is connected
   * @param sessionOpen whether the client has opened the robot
   */
  public record RobotView(
      int index,
      String name,
      String subtype,
      ArPose truePose,
      ArPose odometryPose,
      List<ArPose> footprint,
      List<SonarView> sonar,
      SimLaserScan laser,
      int stallAndBumpers,
      double vel,
      double rotVel,
      boolean motorsEnabled,
      boolean clientConnected,
      boolean sessionOpen) {

    /** Copies the lists. */
    public RobotView {
      footprint = List.copyOf(footprint);
      sonar = List.copyOf(sonar);
    }
  }

  /**
   * One sonar transducer in a {@link RobotView}: where it is and what it last measured.
   *
   * @param x world x, mm
   * @param y world y, mm
   * @param thDeg world heading, degrees
   * @param coneDeg opening of its cone, degrees
   * @param rangeMm last reported range, mm
   * @param echo whether the last firing got an echo
   */
  public record SonarView(
      double x, double y, double thDeg, double coneDeg, int rangeMm, boolean echo) {}
}
