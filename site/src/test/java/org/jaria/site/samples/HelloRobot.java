package org.jaria.site.samples;

// tag::file[]
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArRobotConnector;
import org.jaria.util.ArArgumentParser;

/**
 * The getting-started program: connect to a robot or the simulator, drive a one-metre square with
 * motion commands, print where the robot thinks it is. Runs as a single source file: {@code java
 * -cp "tools/target/jaria-tools.jar:tools/target/lib/*" HelloRobot.java -rh localhost}.
 */
public final class HelloRobot {

  private HelloRobot() {}

  // tag::main[]
  public static void main(String[] args) throws InterruptedException {
    ArRobot robot = new ArRobot();
    ArRobotConnector connector = new ArRobotConnector(new ArArgumentParser(args), robot);
    if (!connector.connectRobot()) {
      System.err.println("Could not connect: " + robot.getConnectFailure());
      System.exit(1);
    }
    robot.runAsync(true); // the robot's cycle now runs on a thread of its own
    System.out.println("Connected to " + robot.getRobotName() + ", a " + robot.getRobotSubType());

    square(robot, 1000);

    System.out.println("Done; the robot believes it is at " + robot.getPose());
    robot.close();
  }

  // end::main[]

  // tag::square[]
  /** Drives a square of {@code side} mm, turning left at each corner. */
  static void square(ArRobot robot, double side) throws InterruptedException {
    robot.enableMotors();
    for (int corner = 0; corner < 4; corner++) {
      robot.move(side); // a motion command: ARCOS drives the distance and stops
      while (!robot.isMoveDone()) {
        robot.getClock().sleepMillis(50); // wait on the robot's clock, not Thread.sleep
      }
      robot.setDeltaHeading(90); // turn 90 degrees to the left
      while (!robot.isHeadingDone()) {
        robot.getClock().sleepMillis(50);
      }
    }
  }
  // end::square[]
}
// end::file[]
