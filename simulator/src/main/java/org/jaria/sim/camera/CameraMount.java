package org.jaria.sim.camera;

import org.jaria.geom.ArPose;
import org.jaria.sim.serial.PtzHead;

/**
 * The robot a {@link SimCamera} is mounted on, as far as the camera needs it: where the robot
 * really is and its number. The simulator's robot is one ({@code SimRobot} implements this); see
 * {@link CameraScene} for why the camera does not name the simulator's classes.
 */
public interface CameraMount {

  /** The robot's number in its world (0 for the first). */
  int getIndex();

  /** Where the robot really is (not where its odometry thinks it is). */
  ArPose getTruePose();

  /** Where the robot's pan/tilt head points (the camera follows it when told to). */
  PtzHead.Pointing getPtzPointing();
}
