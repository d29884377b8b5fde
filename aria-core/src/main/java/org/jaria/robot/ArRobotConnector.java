package org.jaria.robot;

import java.io.IOException;
import java.util.Locale;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.ArTcpConnection;
import org.jaria.connection.RobotAddress;
import org.jaria.util.ArArgumentParser;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Connects an {@link ArRobot} the way ARIA's programs do (ARIA's {@code ArRobotConnector} / {@code
 * ArSimpleConnector}): from command-line options, trying a simulator on this computer first and the
 * robot's serial port second, so the same program runs against the simulator on a laptop and on the
 * robot's own computer unchanged.
 *
 * <p>Options: {@code -robotPort|-rp PORT} serial port (default {@code /dev/ttyS0}, COM1 on
 * Windows); {@code -robotBaud|-rb BAUD} (default 9600); {@code -remoteHost|-rh HOST} connect by TCP
 * to this host instead; {@code -remoteRobotTcpPort|-rrtp PORT} (default 8101); {@code
 * -remoteIsSim|-ris} nothing more (accepted for ARIA compatibility); {@code -help}.
 */
public class ArRobotConnector {

  private static final Logger log = LoggerFactory.getLogger(ArRobotConnector.class);

  private final ArArgumentParser parser;
  private ArRobot robot;
  private String robotPort;
  private int robotBaud = ArSerialConnection.DEFAULT_BAUD;
  private String remoteHost;
  private int remotePort = ArTcpConnection.DEFAULT_PORT;
  private boolean parsed;
  private String lastOpenFailure = "no connection could be opened";
  private boolean lookedForSimulator;

  /** The serial port tried when no option names one (tests give one that is known to fail). */
  String fallbackSerialPort = defaultSerialPort();

  /** A connector for {@code robot} that takes its options from {@code parser}. */
  public ArRobotConnector(ArArgumentParser parser, ArRobot robot) {
    this.parser = parser;
    this.robot = robot;
  }

  /**
   * Takes this connector's options from the parser.
   *
   * @return false if an option's value is missing or invalid (the reason is logged)
   */
  public boolean parseArgs() {
    try {
      String port = parser.checkParameterArgument("-robotPort", "-rp");
      if (port != null) {
        robotPort = port;
      }
      robotBaud = parser.checkParameterArgumentInteger(robotBaud, "-robotBaud", "-rb");
      String host = parser.checkParameterArgument("-remoteHost", "-rh");
      if (host != null) {
        remoteHost = host;
      }
      remotePort = parser.checkParameterArgumentInteger(remotePort, "-remoteRobotTcpPort", "-rrtp");
      parser.checkArgument("-remoteIsSim", "-ris");
      parser.checkHelp();
      parsed = true;
      return true;
    } catch (IllegalArgumentException e) {
      log.error("{}", e.getMessage());
      return false;
    }
  }

  /** The options this connector understands, for a program's usage message. */
  public static String optionsHelp() {
    return String.join(
        System.lineSeparator(),
        "Robot connection options:",
        "  -robotPort, -rp <port>            serial port of the robot (default "
            + defaultSerialPort()
            + ")",
        "  -robotBaud, -rb <baud>            serial baud rate (default 9600)",
        "  -remoteHost, -rh <host>           connect by TCP to this host (a simulator or a bridge)",
        "  -remoteRobotTcpPort, -rrtp <port> TCP port (default 8101)",
        "  -help                             show this help");
  }

  /** Prints {@link #optionsHelp()} to standard output. */
  public void logOptions() {
    System.out.println(optionsHelp());
  }

  /** The serial port tried when none is given. */
  public static String defaultSerialPort() {
    return System.getProperty("os.name", "").toLowerCase(Locale.ROOT).startsWith("windows")
        ? "COM1"
        : ArSerialConnection.DEFAULT_PORT;
  }

  /**
   * Chooses and opens the connection (remote host if given; else a simulator on localhost if one
   * answers; else the serial port), sets it on the robot, and connects with the handshake.
   *
   * @return whether the robot is connected; if not, {@link ArRobot#getConnectFailure()} says why
   *     (once: the connector leaves it to the program to say)
   */
  public boolean connectRobot() {
    if (robot == null) {
      throw new IllegalStateException("no robot given: use connectRobot(robot)");
    }
    if (!parsed && !parseArgs()) {
      return false;
    }
    ArDeviceConnection conn = choose();
    if (conn == null) {
      robot.link.openFailed(lastOpenFailure);
      return false;
    }
    robot.setDeviceConnection(conn);
    if (robot.blockingConnect()) {
      return true;
    }
    if (lookedForSimulator) {
      // Say where the simulator was looked for, not only what the serial port answered.
      robot.link.explainFailure(noSimulator(fallbackSerialPort) + robot.link.failure());
    }
    return false;
  }

  /** Connects {@code r} (ARIA's {@code ArSimpleConnector::connectRobot(ArRobot*)}). */
  public boolean connectRobot(ArRobot r) {
    this.robot = r;
    return connectRobot();
  }

  /** The connection {@link #connectRobot()} would use, opened; null (logged) if none opens. */
  public ArDeviceConnection chooseConnection() {
    ArDeviceConnection c = choose();
    if (c == null) {
      log.warn("{}", lastOpenFailure);
    }
    return c;
  }

  private ArDeviceConnection choose() {
    lookedForSimulator = false;
    if (remoteHost != null) {
      return open(new ArTcpConnection(remoteHost, remotePort, clock()));
    }
    if (robotPort == null) {
      ArTcpConnection sim = new ArTcpConnection("localhost", remotePort, clock());
      try {
        sim.open();
        log.info("found a simulator on localhost:{}", remotePort);
        return sim;
      } catch (IOException e) {
        log.info("no simulator on localhost:{}; trying the serial port", remotePort);
        lookedForSimulator = true;
      }
    }
    String port = robotPort != null ? robotPort : fallbackSerialPort;
    ArDeviceConnection serial = open(new ArSerialConnection(port, robotBaud, clock()));
    if (serial == null && lookedForSimulator) {
      lastOpenFailure = noSimulator(port) + lastOpenFailure;
    }
    return serial;
  }

  /** The first half of a failure when no option was given: where the simulator was looked for. */
  private String noSimulator(String serialPort) {
    return "no simulator on localhost:"
        + remotePort
        + " (start one with ./jaria sim, or give its host with -rh), so tried the serial port "
        + serialPort
        + ": ";
  }

  private org.jaria.clock.Clock clock() {
    return robot == null ? org.jaria.clock.Clock.system() : robot.getClock();
  }

  private ArDeviceConnection open(ArDeviceConnection c) {
    try {
      RobotAddress.openExplained(c, "-rp");
      return c;
    } catch (IOException e) {
      lastOpenFailure = e.getMessage();
      log.debug("{}", lastOpenFailure);
      return null;
    }
  }

  /** The serial port option (null if not given). */
  public String getRobotPort() {
    return robotPort;
  }

  /** The baud option. */
  public int getRobotBaud() {
    return robotBaud;
  }

  /** The remote host option (null if not given). */
  public String getRemoteHost() {
    return remoteHost;
  }

  /** The TCP port option. */
  public int getRemotePort() {
    return remotePort;
  }
}
