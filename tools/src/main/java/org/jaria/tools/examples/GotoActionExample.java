package org.jaria.tools.examples;

import java.io.PrintStream;
import java.util.function.Consumer;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionStallRecover;
import org.jaria.protocol.ArCommands;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArRobotConnector;
import org.jaria.util.ArArgumentParser;

/**
 * The thesis's obstacle-avoidance program (§6.3, ARIA's {@code gotoActionExample.cpp}), line by
 * line in Java: connect, add the sonar, and let five actions wander the robot around obstacles.
 *
 * <pre>
 * java ... GotoActionExample -rh localhost        (a simulator: ./jaria sim)
 * java ... GotoActionExample -rp /dev/ttyS0       (a real robot)
 * </pre>
 */
public final class GotoActionExample {

  private GotoActionExample() {}

  /** Runs the program with ARIA's command-line options; exits with its status. */
  public static void main(String[] args) {
    System.exit(run(args, robot -> {}));
  }

  /**
   * The program itself. {@code started} is given the robot once it runs, so a caller (the demo
   * command, a test) can watch it or stop it with {@code robot.stopRunning()}; what goes wrong (no
   * robot, an unknown option) is said on {@code err}, where a caller with options of its own
   * collects it to explain it in its own words.
   *
   * @return the exit status: 0 normal, 1 bad arguments or no robot
   */
  public static int run(String[] args, Consumer<ArRobot> started, PrintStream err) {
    ArArgumentParser argParser = new ArArgumentParser(args);
    argParser.loadDefaultArguments();
    ArRobot robot = new ArRobot();
    ArRobotConnector robotConnector = new ArRobotConnector(argParser, robot);

    if (!robotConnector.connectRobot()) {
      err.println("Could not connect to the robot: " + robot.getConnectFailure());
      if (argParser.checkHelpAndWarnUnparsed()) {
        err.println(ArRobotConnector.optionsHelp());
      }
      return 1;
    }
    if (!argParser.checkHelpAndWarnUnparsed()) {
      err.println(ArRobotConnector.optionsHelp());
      robot.close();
      return 1;
    }

    System.out.println(
        """
        This program will make the robot wander around. It uses some avoidance
        actions if obstacles are detected, otherwise it just has a constant forward
        velocity.

        Press CTRL-C to exit.""");

    ArSonarDevice sonar = new ArSonarDevice();
    robot.addRangeDevice(sonar);

    robot.runAsync(true);

    // turn on the motors, turn off amigobot sounds
    robot.enableMotors();
    robot.comInt(ArCommands.SOUNDTOG, 0);

    // add a set of actions that combine together to effect the wander behavior
    ArActionStallRecover recover = new ArActionStallRecover();
    ArActionBumpers bumpers = new ArActionBumpers();
    ArActionAvoidFront avoidFrontNear = new ArActionAvoidFront("Avoid Front Near", 225, 0);
    ArActionAvoidFront avoidFrontFar = new ArActionAvoidFront();
    ArActionConstantVelocity constantVelocity =
        new ArActionConstantVelocity("Constant Velocity", 400);
    robot.addAction(recover, 100);
    robot.addAction(bumpers, 75);
    robot.addAction(avoidFrontNear, 50);
    robot.addAction(avoidFrontFar, 49);
    robot.addAction(constantVelocity, 25);

    started.accept(robot);

    // wait for the robot's cycle to end (disconnection or stopRunning()) before exiting
    try {
      robot.waitForRunExit();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    robot.close();
    return 0;
  }

  /** The program, saying what goes wrong on standard error. */
  public static int run(String[] args, Consumer<ArRobot> started) {
    return run(args, started, System.err);
  }
}
