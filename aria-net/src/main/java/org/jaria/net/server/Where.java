package org.jaria.net.server;

/** Where a request handler runs. */
public enum Where {
  /**
   * On the robot's cycle thread, between two cycles' tasks, with the robot locked: for anything
   * that changes what the robot does (modes, actions, motion). Keep such handlers short — a few
   * microseconds — they delay the robot's cycle. On a server without a robot they run on a worker.
   */
  CYCLE,
  /**
   * On one of the server's worker threads, off the robot's cycle: for anything slow (files,
   * configuration, localization requests) or that only reads thread-safe state.
   */
  WORKER
}
