package org.example.consumer;

import org.jaria.robot.ArRobot;

/** A user's robot program: drive straight ahead with ARIA's motion commands. */
public final class Forward {

  private Forward() {}

  /**
   * Drives {@code mm} millimetres straight ahead and returns when the move is done. It waits on
   * the robot's clock, never {@code Thread.sleep}: on a real robot that is the same thing, and on
   * the simulator's virtual time it is what lets simulated time pass.
   *
   * @param robot a connected robot
   * @param mm how far to drive, in millimetres
   * @throws InterruptedException if the thread is interrupted while waiting
   */
  public static void drive(ArRobot robot, double mm) throws InterruptedException {
    robot.enableMotors();
    robot.move(mm); // a motion command: the robot drives the distance and stops
    while (!robot.isMoveDone()) {
      robot.getClock().sleepMillis(50);
    }
  }
}
