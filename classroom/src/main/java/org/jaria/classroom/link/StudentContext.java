package org.jaria.classroom.link;

import org.jaria.classroom.grading.Programs;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.robot.ArRobot;

/** What a {@link StudentSide} works with in the student's JVM. */
public interface StudentContext {

  /** The connected robot (on the link's virtual clock). */
  ArRobot robot();

  /** The virtual clock the grader drives. */
  Clock clock();

  /**
   * The device channel {@code name} the grader opened beside the robot's (e.g. "acts").
   *
   * @throws IllegalArgumentException if there is none by that name
   */
  ArDeviceConnection channel(String name);

  /** The student's solution class. */
  Class<?> solution();

  /** The sequential program the grader's PROGRAM frame runs. */
  void setProgram(Programs.Body program);
}
