package org.jaria.tools.examples;

import java.util.function.Consumer;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionKeydrive;
import org.jaria.action.ArActionLimiterBackwards;
import org.jaria.action.ArActionLimiterForwards;
import org.jaria.acts.ArACTS_1_2;
import org.jaria.input.ArKeyHandler;
import org.jaria.protocol.ArCommands;
import org.jaria.ptz.ArPTZ;
import org.jaria.ptz.ArVCC4;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArSimpleConnector;
import org.jaria.util.ArArgumentParser;

/**
 * The thesis's vision-control program (§6.4, {@code actsColorFollowingExample.cpp}): the robot
 * drives towards the largest blob of ACTS channel 1, with speed limiters for obstacles, and stops
 * when it loses the target. On a real robot the camera is a Canon VC-C4 on the robot's AUX port
 * (driven through TTY2); on the simulator it is the simulated camera.
 *
 * <p>One option is added to ARIA's: {@code -actsPort N} when ACTS is not on port 5001.
 */
public final class ActsColorFollowingExample {

  private ActsColorFollowingExample() {}

  /** Runs against a real robot (VC-C4 on the AUX port) or a simulator; exits with its status. */
  public static void main(String[] args) throws java.io.IOException {
    try (ArKeyHandler keyHandler = ArKeyHandler.forTerminal()) {
      System.exit(run(args, null, keyHandler, robot -> {}));
    }
  }

  /** The thesis's toggleAction: switches an action on or off, saying which. */
  public static void toggleAction(ArAction action) {
    if (action.isActive()) {
      action.deactivate();
      System.out.println(action.getName() + " action is now deactivated.");
    } else {
      action.activate();
      System.out.println(action.getName() + " action is now activated.");
    }
  }

  /** What the program says once it runs, as ARIA's example does. */
  public static final String RUNNING =
      "Running. Train ACTS to detect a color to drive towards an object, or use 'a' key to"
          + " switch to keyboard driving mode.";

  /**
   * The program. {@code camera} is the pan/tilt/zoom camera to use, or null for a VC-C4 on the
   * robot's AUX serial port; {@code keyHandler} gives the keys ('a' switches keyboard driving on
   * and off, the arrows drive, Escape ends); {@code running} is what it says once it runs (ARIA's
   * {@link #RUNNING}, or what a caller that trained ACTS already, or reads no keys, says).
   *
   * @return 0 normal, 1 no robot, 2 no ACTS
   */
  public static int run(
      String[] args,
      ArPTZ camera,
      ArKeyHandler keyHandler,
      Consumer<ArRobot> started,
      String running) {
    // The robot
    ArRobot robot = new ArRobot();
    // Sonar, for basic obstacle avoidance
    ArSonarDevice sonar = new ArSonarDevice();
    // Camera (Canon VC-C4 through the robot's AUX port, unless one is given)
    ArPTZ vcc4 = camera != null ? camera : new ArVCC4(robot);
    // ACTS, for colour blob tracking
    ArACTS_1_2 acts = new ArACTS_1_2(robot.getClock());
    // Command-line arguments
    ArArgumentParser argParser = new ArArgumentParser(args);
    argParser.loadDefaultArguments();
    int actsPort = argParser.checkParameterArgumentInteger(5001, "-actsPort");
    // Simple way to connect (takes arguments from argParser)
    ArSimpleConnector simpleConnector = new ArSimpleConnector(argParser);
    if (!simpleConnector.parseArgs() || !argParser.checkHelpAndWarnUnparsed()) {
      simpleConnector.logOptions();
      return 1;
    }

    // Limiters of movement (if obstacles are detected)
    ArActionLimiterForwards limiter =
        new ArActionLimiterForwards("speed limiter near", 350, 800, 200);
    ArActionLimiterForwards limiterFar =
        new ArActionLimiterForwards("speed limiter far", 400, 1250, 300);
    ArActionLimiterBackwards backwardsLimiter = new ArActionLimiterBackwards();
    ArActionConstantVelocity stop = new ArActionConstantVelocity("stop", 0);
    // The action that follows the colour
    Chase chase = new Chase(acts, vcc4);
    // Keyboard teleoperation
    ArActionKeydrive keydriveAction = new ArActionKeydrive(keyHandler);
    // 'a' switches keyboard driving on and off
    keyHandler.addKeyHandler('a', () -> toggleAction(keydriveAction));
    // Attach the keys to the robot
    keyHandler.attachKeyHandler(robot, true, null);

    // Add the sonar to the robot
    robot.addRangeDevice(sonar);

    // Connect to the robot
    if (!simpleConnector.connectRobot(robot)) {
      System.err.println(
          "Error: Could not connect to robot... exiting: " + robot.getConnectFailure());
      return 1;
    }
    // Open a connection to ACTS
    if (!acts.openPort(robot, "localhost", actsPort)) {
      System.err.println("Error: Could not connect to ACTS... exiting. " + acts.getOpenMessage());
      robot.close();
      return 2;
    }
    // Initialise the camera
    vcc4.init();
    // Keep the robot to a gentle top speed
    robot.setAbsoluteMaxTransVel(400);
    // Enable the motors
    robot.comInt(ArCommands.ENABLE, 1);

    // Add the actions in decreasing order of importance
    robot.addAction(limiter, 7);
    robot.addAction(limiterFar, 6);
    robot.addAction(backwardsLimiter, 5);
    robot.addAction(keydriveAction, 4);
    robot.addAction(chase, 3);
    robot.addAction(stop, 1);
    // Start with keyboard driving off: 'a' turns it on
    keydriveAction.deactivate();

    System.out.println(running);
    robot.runAsync(true);
    started.accept(robot);
    try {
      robot.waitForRunExit();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    acts.close();
    robot.close();
    return 0;
  }

  /** The program, saying what ARIA's says once it runs ({@link #RUNNING}). */
  public static int run(
      String[] args, ArPTZ camera, ArKeyHandler keyHandler, Consumer<ArRobot> started) {
    return run(args, camera, keyHandler, started, RUNNING);
  }
}
