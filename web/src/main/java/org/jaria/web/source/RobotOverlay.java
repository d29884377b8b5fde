package org.jaria.web.source;

import org.jaria.web.model.RobotFrame;

/**
 * Adds what a robot's own software knows to the simulator's picture of it: where it believes it is,
 * its particles, its path, its status. Thread-safe.
 */
@FunctionalInterface
public interface RobotOverlay {

  /** {@code base} with this overlay's parts added. */
  RobotFrame apply(RobotFrame base);
}
