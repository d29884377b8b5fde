package org.jaria.tools.examples;

import java.io.PrintStream;
import java.util.List;
import java.util.function.Consumer;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionGoto;
import org.jaria.action.ArActionStallRecover;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArRobotConnector;
import org.jaria.util.ArArgumentParser;

/**
 * Goes to a list of poses with ArActionGoto while avoiding obstacles (the "goto" application of the
 * thesis's chapter 6): each goal is relative to where the robot started; when one is reached the
 * next is set, until the list is done.
 */
public final class GotoExample {

  private GotoExample() {}

  /** A one-metre-and-a-half square, back to the start. */
  public static final List<ArPose> SQUARE =
      List.of(new ArPose(1500, 0), new ArPose(1500, 1500), new ArPose(0, 1500), new ArPose(0, 0));

  /** Runs the square with ARIA's command-line options. */
  public static void main(String[] args) {
    System.exit(run(args, SQUARE, System.out, robot -> {}));
  }

  /**
   * The program; what goes wrong (no robot, an unknown option) is said on {@code err}.
   *
   * @return 0 when every goal was reached, 1 no robot, 2 stopped before the end
   */
  public static int run(
      String[] args,
      List<ArPose> goals,
      PrintStream out,
      Consumer<ArRobot> started,
      PrintStream err) {
    ArArgumentParser parser = new ArArgumentParser(args);
    ArRobot robot = new ArRobot();
    ArRobotConnector connector = new ArRobotConnector(parser, robot);
    if (!connector.connectRobot() || !parser.checkHelpAndWarnUnparsed()) {
      err.println("Could not connect to the robot: " + robot.getConnectFailure());
      return 1;
    }
    robot.addRangeDevice(new ArSonarDevice());
    ArActionGoto gotoPose = new ArActionGoto("goto", goals.get(0), 100, 400, 150, 7);
    robot.addAction(new ArActionStallRecover(), 100);
    robot.addAction(new ArActionBumpers(), 75);
    robot.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0), 50);
    robot.addAction(new ArActionAvoidFront(), 49);
    robot.addAction(gotoPose, 40);
    int[] index = {0};
    robot.addUserTask(
        "next goal",
        10,
        () -> {
          if (gotoPose.haveAchievedGoal() && index[0] < goals.size()) {
            out.printf(
                "reached goal %d %s at %s%n", index[0] + 1, goals.get(index[0]), robot.getPose());
            index[0]++;
            if (index[0] < goals.size()) {
              gotoPose.setGoal(goals.get(index[0]));
            } else {
              out.println("all goals reached");
              robot.stopRunning();
            }
          }
        });
    robot.enableMotors();
    robot.runAsync(true);
    started.accept(robot);
    try {
      robot.waitForRunExit();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    robot.close();
    return index[0] == goals.size() ? 0 : 2;
  }

  /** The program, saying what goes wrong on {@code out} too. */
  public static int run(
      String[] args, List<ArPose> goals, PrintStream out, Consumer<ArRobot> started) {
    return run(args, goals, out, started, out);
  }
}
