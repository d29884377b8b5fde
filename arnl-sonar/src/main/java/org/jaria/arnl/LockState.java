package org.jaria.arnl;

/** How sure the localization task is of the robot's pose (ARNL's {@code LockState}). */
public enum LockState {
  /** No initial pose yet. */
  LOCK_NOT_INITIALIZED,
  /** Updates keep failing: the robot is lost (it should stop; recovery scatters particles). */
  LOST,
  /** Some recent updates failed, not yet enough to count as lost. */
  LOST_LOCK,
  /** The last update passed. */
  LOCKED
}
