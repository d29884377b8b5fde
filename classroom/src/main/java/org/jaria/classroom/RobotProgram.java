package org.jaria.classroom;

import org.jaria.robot.ArRobot;

/**
 * A sequential robot program: command the robot, wait, command again. The grader gives it a robot
 * that is already connected and running; the program returns when it is done.
 *
 * <p>Wait on the robot's clock, never with {@code Thread.sleep}: on the simulator time only passes
 * while your program waits on {@code robot.getClock()}, which is what makes a two-minute run take a
 * fraction of a second.
 *
 * <pre>{@code
 * public class Forward implements RobotProgram {
 *   public void run(ArRobot robot) throws InterruptedException {
 *     robot.enableMotors();
 *     robot.move(1000);
 *     while (!robot.isMoveDone()) {
 *       robot.getClock().sleepMillis(50);
 *     }
 *   }
 * }
 * }</pre>
 */
@FunctionalInterface
public interface RobotProgram {

  /**
   * Runs the program on {@code robot}.
   *
   * @throws InterruptedException if the program is stopped while it waits (let it propagate)
   */
  void run(ArRobot robot) throws InterruptedException;
}
