package org.jaria.web.source;

import org.jaria.web.model.MapLayer;
import org.jaria.web.model.WorldFrame;

/**
 * Where the pictures come from: the simulator's world, a robot that localizes, or both. The
 * server's publisher thread asks for a frame several times a second; an implementation takes it
 * from state that is already consistent (a snapshot), so asking never waits on the robot's cycle
 * for longer than a copy. Thread-safe.
 */
public interface FrameSource {

  /** The map now (the same object while it does not change). */
  MapLayer map();

  /** Everything that moves, now. */
  WorldFrame frame();
}
