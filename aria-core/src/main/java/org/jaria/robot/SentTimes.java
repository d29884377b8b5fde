package org.jaria.robot;

/**
 * When state reflection last sent a translation command, a rotation command and a PULSE (clock
 * nanoseconds). Shared by the direct-motion and the action halves of the reflection, because the
 * 500 ms refresh and the idle PULSE depend on whatever went out last, whoever sent it.
 */
final class SentTimes {
  long trans;
  long rot;
  long pulse;

  void resetTo(long now) {
    trans = now;
    rot = now;
    pulse = now;
  }
}
