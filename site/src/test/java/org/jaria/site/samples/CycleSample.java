package org.jaria.site.samples;

import java.io.PrintStream;
import java.util.Locale;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/** Tasks in the robot's cycle (the ArRobot guide). */
public final class CycleSample {

  private volatile int closestAhead = -1;

  /** Adds a sensor-interpretation task and a user task to {@code robot}. */
  public CycleSample(ArRobot robot, PrintStream out) {
    // tag::tasks[]
    robot.addRangeDevice(new ArSonarDevice());
    // Sensor interpretation: runs every cycle right after the SIP is read, before the actions.
    robot.addSensorInterpTask(
        "closest ahead", 50, () -> closestAhead = robot.getClosestSonarRange(-30, 30));
    // User task: runs every cycle after the motion commands have been sent. Keep it short: the
    // whole cycle has 100 ms.
    robot.addUserTask(
        "report",
        50,
        () -> {
          if (robot.getCounter() % 10 == 0) { // once a second
            out.printf(Locale.ROOT, "%s  closest ahead %d mm%n", robot.getPose(), closestAhead);
          }
        });
    // end::tasks[]
  }

  /** The last reading of the task. */
  public int closestAhead() {
    return closestAhead;
  }
}
