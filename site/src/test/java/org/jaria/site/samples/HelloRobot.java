package org.jaria.site.samples;

// tag::file[]
import java.util.function.BooleanSupplier;
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArRobotConnector;
import org.jaria.util.ArArgumentParser;

/**
 * The getting-started program: connect to a robot or the simulator, drive a one-metre square with
 * motion commands, print where the robot thinks it is. Runs as a single source file: {@code java
 * -cp "tools/target/jaria-tools.jar:tools/target/lib/*" HelloRobot.java -rh localhost}.
 */
public final class HelloRobot {

  /** How long one side or one turn may take before the program gives up (robot's clock). */
  static final long GIVE_UP_MILLIS = 15_000;

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

    boolean drove = square(robot, 1000);

    System.out.println(
        (drove ? "Done" : "Stopped early") + "; the robot believes it is at " + robot.getPose());
    robot.close();
    System.exit(drove ? 0 : 2);
  }

  // end::main[]

  // tag::square[]
  /**
   * Drives a square of {@code side} mm, turning left at each corner.
   *
   * @return true if it drove the whole square; false if the robot got stuck and it gave up
   */
  static boolean square(ArRobot robot, double side) throws InterruptedException {
    robot.enableMotors();
    for (int corner = 0; corner < 4; corner++) {
      robot.move(side); // a motion command: ARCOS drives the distance and stops
      if (!waitUntil(robot, robot::isMoveDone)) {
        return false;
      }
      robot.setDeltaHeading(90); // turn 90 degrees to the left
      if (!waitUntil(robot, robot::isHeadingDone)) {
        return false;
      }
    }
    return true;
  }

  /**
   * Waits for a motion command to finish. A wall in the way stalls the wheels and the command never
   * finishes, so this gives up (and stops the robot) on a stall or after {@link #GIVE_UP_MILLIS}
   * instead of waiting for ever.
   */
  static boolean waitUntil(ArRobot robot, BooleanSupplier done) throws InterruptedException {
    long giveUpAt = robot.getClock().millis() + GIVE_UP_MILLIS;
    while (!done.getAsBoolean()) {
      boolean stalled = robot.isLeftMotorStalled() || robot.isRightMotorStalled();
      if (stalled || robot.getClock().millis() > giveUpAt) {
        robot.stop();
        System.out.println(
            stalled
                ? "The robot is stuck (a wheel stalled: something is in the way); giving up."
                : "The move did not finish in " + GIVE_UP_MILLIS / 1000 + " s; giving up.");
        return false;
      }
      robot.getClock().sleepMillis(50); // wait on the robot's clock, not Thread.sleep
    }
    return true;
  }
  // end::square[]
}
// end::file[]
