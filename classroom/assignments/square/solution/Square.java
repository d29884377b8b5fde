import org.jaria.classroom.RobotProgram;
import org.jaria.robot.ArRobot;

/** Assignment 1 (reference solution): a 2 m square, counter-clockwise, with motion commands. */
public class Square implements RobotProgram {

  private static final double SIDE_MM = 2000;

  @Override
  public void run(ArRobot robot) throws InterruptedException {
    robot.enableMotors();
    for (int side = 0; side < 4; side++) {
      robot.move(SIDE_MM);
      while (!robot.isMoveDone()) {
        robot.getClock().sleepMillis(50);
      }
      robot.setDeltaHeading(90);
      while (!robot.isHeadingDone()) {
        robot.getClock().sleepMillis(50);
      }
    }
  }
}
