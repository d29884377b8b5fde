package org.jaria.tools.examples;

import java.io.PrintStream;
import java.util.Locale;
import java.util.function.Consumer;
import org.jaria.action.ArActionKeydrive;
import org.jaria.gyro.ArAnalogGyro;
import org.jaria.input.ArKeyHandler;
import org.jaria.protocol.ArCommands;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.robot.ArSimpleConnector;

/**
 * The thesis's turn-control program (§6.2, {@code gyroExample.cpp}): keys 1–0 turn the robot at
 * 10…100 deg/s counter-clockwise, q…p clockwise, a/s/d/f turn it to heading 0/90/180/270, space
 * stops, the arrow keys drive; a user task prints the gyro's heading, the wheels' heading and the
 * fused heading the robot uses.
 */
public final class GyroExample {

  private GyroExample() {}

  /** The thesis's GyroTask: binds the keys and prints the headings each cycle. */
  public static final class GyroTask {
    private final ArAnalogGyro gyro;
    private final ArRobot robot;
    private final PrintStream out;
    private final int printEvery;
    private int cycles;

    /**
     * Adds the task to {@code robot} and the turn keys to {@code keyHandler}; prints every {@code
     * printEvery} cycles (1 as in ARIA: ten lines a second).
     */
    public GyroTask(ArRobot robot, ArKeyHandler keyHandler, PrintStream out, int printEvery) {
      this.robot = robot;
      this.out = out;
      this.printEvery = Math.max(1, printEvery);
      robot.addUserTask("GyroTask", 50, this::doTask);
      gyro = new ArAnalogGyro(robot);
      String ccw = "1234567890";
      String cw = "qwertyuiop";
      for (int i = 0; i < 10; i++) {
        double speed = 10 * (i + 1);
        keyHandler.addKeyHandler(ccw.charAt(i), () -> robot.setRotVel(speed));
        keyHandler.addKeyHandler(cw.charAt(i), () -> robot.setRotVel(-speed));
      }
      keyHandler.addKeyHandler(ArKeyHandler.SPACE, robot::stop);
      keyHandler.addKeyHandler('a', () -> robot.setHeading(0));
      keyHandler.addKeyHandler('s', () -> robot.setHeading(90));
      keyHandler.addKeyHandler('d', () -> robot.setHeading(180));
      keyHandler.addKeyHandler('f', () -> robot.setHeading(270));
    }

    /** Prints the gyro's, the wheels' and the fused heading. */
    void doTask() {
      if (cycles++ % printEvery != 0) {
        return;
      }
      out.printf(
          Locale.ROOT,
          "gyro %10f robot %10f mixed %10f temp %d ave %g%n",
          gyro.getHeading(),
          robot.getRawEncoderPose().getTh(),
          robot.getTh(),
          gyro.getTemperature(),
          gyro.getAverage());
    }

    /** The gyro. */
    public ArAnalogGyro gyro() {
      return gyro;
    }
  }

  /**
   * Adds the keydrive action at priority 45. Space belongs to both the turn keys (it stops a turn
   * started with a motion command) and the keydrive action (it zeroes its speeds); the action would
   * find the key taken and warn, so it takes its keys first and then space does both.
   */
  static void addKeydrive(ArRobot robot, ArKeyHandler keyHandler, ArActionKeydrive keydrive) {
    Runnable stopTurn = keyHandler.getKeyHandler(ArKeyHandler.SPACE);
    keyHandler.remKeyHandler(ArKeyHandler.SPACE);
    robot.addAction(keydrive, 45);
    Runnable keydriveSpace = keyHandler.getKeyHandler(ArKeyHandler.SPACE);
    keyHandler.remKeyHandler(ArKeyHandler.SPACE);
    keyHandler.addKeyHandler(
        ArKeyHandler.SPACE,
        () -> {
          if (keydriveSpace != null) {
            keydriveSpace.run();
          }
          if (stopTurn != null) {
            stopTurn.run();
          }
        });
  }

  /** Runs with the terminal's keys; exits with the program's status. */
  public static void main(String[] args) throws java.io.IOException {
    try (ArKeyHandler keys = ArKeyHandler.forTerminal()) {
      System.exit(run(args, keys, System.out, 1, robot -> {}));
    }
  }

  /** What the program says of its keys before it connects. */
  public static final String KEYS =
      "This program lets you drive the robot with the keyboard: arrows drive, space stops,\n"
          + "1-0 and q-p turn, a/s/d/f turn to 0/90/180/270 degrees. ESC exits.";

  /**
   * The program, with keys from {@code keyHandler} (a terminal, or keys fed by a caller), saying
   * {@code intro} before it connects ({@link #KEYS}, or what a caller that presses the keys itself
   * says).
   *
   * @return 0 normal, 1 no robot
   */
  public static int run(
      String[] args,
      ArKeyHandler keyHandler,
      PrintStream out,
      int printEvery,
      Consumer<ArRobot> started,
      String intro) {
    ArRobot robot = new ArRobot();
    ArActionKeydrive keydriveAct = new ArActionKeydrive(keyHandler);
    new GyroTask(robot, keyHandler, out, printEvery);
    ArSonarDevice sonar = new ArSonarDevice();
    ArSimpleConnector connector = new ArSimpleConnector(args);
    if (!connector.parseArgs()) {
      connector.logOptions();
      return 1;
    }
    out.println(intro);
    robot.addRangeDevice(sonar);
    if (!connector.connectRobot(robot)) {
      out.println("Could not connect to robot... exiting: " + robot.getConnectFailure());
      return 1;
    }
    robot.comInt(ArCommands.ENABLE, 1);
    addKeydrive(robot, keyHandler, keydriveAct); // robot.addAction(keydriveAct, 45)
    keyHandler.attachKeyHandler(robot, true, () -> {});
    robot.runAsync(true);
    started.accept(robot);
    try {
      robot.waitForRunExit();
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    robot.close();
    return 0;
  }

  /** The program, saying what its keys do ({@link #KEYS}) before it connects. */
  public static int run(
      String[] args,
      ArKeyHandler keyHandler,
      PrintStream out,
      int printEvery,
      Consumer<ArRobot> started) {
    return run(args, keyHandler, out, printEvery, started, KEYS);
  }
}
