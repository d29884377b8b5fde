import org.jaria.classroom.RobotProgram;
import org.jaria.robot.ArRobot;

/**
 * Assignment 1 (starter): drive a square of 2 m sides, counter-clockwise, with motion commands, and
 * stop where you started.
 *
 * <p>Grade it: {@code ./jaria grade --assignment square FOLDER} (FOLDER holds this file).
 */
public class Square implements RobotProgram {

  @Override
  public void run(ArRobot robot) throws InterruptedException {
    robot.enableMotors();

    // The first side: drive 2000 mm and wait until the move is done. Waiting on the robot's
    // clock (not Thread.sleep) lets simulated time pass.
    robot.move(2000);
    while (!robot.isMoveDone()) {
      robot.getClock().sleepMillis(50);
    }

    // TODO turn 90 degrees to the left (robot.setDeltaHeading) and wait for robot.isHeadingDone()

    // TODO the other three sides and turns (a loop saves typing)
  }
}
