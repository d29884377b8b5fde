package org.jaria.site.samples;

import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionLimiterForwards;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;

/** Actions with priorities (the actions guide). */
public final class ActionsSample {

  private ActionsSample() {}

  /** Gives {@code robot} three actions: drive, slow near obstacles, back off when too close. */
  public static void addActions(ArRobot robot) {
    // tag::priorities[]
    robot.addRangeDevice(new ArSonarDevice());
    robot.addAction(new KeepAway(400), 90); // highest priority: safety first
    robot.addAction(new ArActionLimiterForwards("slow near", 300, 1200, 150), 80);
    robot.addAction(new ArActionConstantVelocity("cruise", 400), 10); // lowest: the default
    robot.enableMotors();
    // end::priorities[]
  }
}
