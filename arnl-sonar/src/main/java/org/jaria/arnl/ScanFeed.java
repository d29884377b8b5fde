package org.jaria.arnl;

import org.jaria.arnl.mcl.SonarScan;
import org.jaria.geom.ArPose;

/**
 * Where a localization task's readings come from (the sonar ring, a laser), prepared for the
 * filter. {@link #note()} and {@link #takeFresh} run on the robot's cycle thread only; {@link
 * #current} may run on any thread.
 */
interface ScanFeed {

  /** On every robot cycle: remembers the readings that arrived since the last cycle. */
  void note();

  /**
   * The readings noted since the last take (and forgets them), prepared in the robot's frame at
   * odometry pose {@code encoderNow}; an empty scan if none.
   */
  SonarScan takeFresh(ArPose encoderNow);

  /**
   * The newest readings (recent ones only), prepared at the robot's current odometry pose {@code
   * encoderNow}, to localize a robot standing still.
   */
  SonarScan current(ArPose encoderNow);

  /** What the readings are, for messages ("sonar echoes", "laser scan"). */
  String what();
}
