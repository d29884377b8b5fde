package org.jaria.tools.demo;

import java.util.Locale;

/**
 * Says when the wandering robot turns away from something. The wander program's only turning
 * actions are its avoidance actions (its constant-velocity action drives straight), so a turn that
 * starts is an avoidance; the line names the side the closest thing is on.
 *
 * <p>A plain decision over values, fed once per robot cycle: {@link #update} returns the line to
 * print when a turn starts, else null.
 */
final class TurnReporter {

  /** Turning faster than this (deg/s) counts as a turn. */
  static final double TURNING_DEG_PER_SEC = 12;

  private boolean turning;

  /**
   * Takes one cycle's readings and returns the line to print if a turn starts now.
   *
   * @param seconds time since the demo started
   * @param rotVel the robot's rotational velocity, deg/s (positive turns left)
   * @param closestLeft the closest sonar reading on the front-left (0..90 degrees), mm, or -1
   * @param closestRight the closest sonar reading on the front-right, mm, or -1
   * @return the line to print if a turn starts now, else null
   */
  String update(double seconds, double rotVel, int closestLeft, int closestRight) {
    boolean now = Math.abs(rotVel) >= TURNING_DEG_PER_SEC;
    boolean starts = now && !turning;
    turning = now;
    if (!starts) {
      return null;
    }
    int range = closest(closestLeft, closestRight);
    String dir = rotVel > 0 ? "left" : "right";
    if (range < 0) {
      return String.format(Locale.ROOT, "t=%5.1fs  turning %s", seconds, dir);
    }
    return String.format(
        Locale.ROOT, "t=%5.1fs  turning %s, away from something %d mm ahead", seconds, dir, range);
  }

  private static int closest(int a, int b) {
    if (a < 0) {
      return b;
    }
    return b < 0 ? a : Math.min(a, b);
  }
}
