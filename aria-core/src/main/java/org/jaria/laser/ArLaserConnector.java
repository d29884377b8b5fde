package org.jaria.laser;

import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.RobotAddress;
import org.jaria.robot.ArRobot;
import org.jaria.util.ArArgumentParser;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Builds and connects a robot's laser the way ARIA programs do (ARIA's {@code ArLaserConnector}):
 * the robot's parameter file says which laser it has and where ({@code LaserType}, {@code
 * LaserPort}, {@code LaserX}, ...), and ARIA's command-line options ({@code -laserType}, {@code
 * -laserPort}, {@code -connectLaser}, ...; see {@link LaserOptions#help()}) override it.
 *
 * <pre>{@code
 * ArLaserConnector lc = new ArLaserConnector(parser, robot);
 * lc.parseArgs();                 // before the robot connects, with the other connectors
 * robotConnector.connectRobot();
 * lc.connectLasers();             // after: the robot's parameters are known now
 * }</pre>
 */
public class ArLaserConnector {

  private static final Logger log = LoggerFactory.getLogger(ArLaserConnector.class);

  private final ArArgumentParser parser;
  private final ArRobot robot;
  private Map<String, String> args = Map.of();
  private boolean parsed;
  private ArLaser laser;
  private String failure = "";

  /** A connector taking its options from {@code parser}, for {@code robot} (may be null). */
  public ArLaserConnector(ArArgumentParser parser, ArRobot robot) {
    this.parser = parser;
    this.robot = robot;
  }

  /**
   * Takes the laser options from the parser.
   *
   * @return false if an option lacks its value (the reason is logged and in {@link #getFailure()})
   */
  public boolean parseArgs() {
    try {
      args = LaserOptions.argsAsKeys(parser);
      parsed = true;
      return true;
    } catch (IllegalArgumentException e) {
      failure = e.getMessage();
      log.error("{}", failure);
      return false;
    }
  }

  /** The options: the robot's parameters (if it has any yet) with the command line on top. */
  public LaserOptions getOptions() {
    Function<String, Optional<String>> raw =
        robot == null ? k -> Optional.empty() : k -> robot.getRobotParams().getRaw(k);
    return LaserOptions.fromParamsAndArgs(raw, args);
  }

  /**
   * Makes the laser the options ask for, set up (connection, mounting, flip, range) but not
   * connected; null if no laser type is given.
   *
   * @throws IllegalArgumentException if the type, port or a choice is not valid
   */
  public static ArLaser createLaser(LaserOptions o, Clock clock) {
    ArLaser l =
        switch (o.normalType()) {
          case "" -> null;
          case "lms2xx" -> new ArLMS2xx("lms2xx_1", o.lmsSettings());
          case "urg" -> new ArUrg("urg_1", o.urgSettings());
          default ->
              throw new IllegalArgumentException(
                  "unknown laser type '" + o.type() + "': use lms2xx (or sick) or urg");
        };
    if (l == null) {
      return null;
    }
    if (o.port().isEmpty()) {
      throw new IllegalArgumentException(
          "no port for the "
              + o.normalType()
              + " laser: give it with -laserPort (e.g. /dev/ttyUSB0)");
    }
    l.setDeviceConnection(connection(o, clock));
    l.setSensorPosition(o.x(), o.y(), o.th());
    l.setFlipped(o.flipped());
    if (o.maxRange() > 0) {
      l.setMaxRange(Math.min(l.getMaxRange(), o.maxRange()));
    }
    return l;
  }

  /** The (unopened) connection for the options' port. */
  static ArDeviceConnection connection(LaserOptions o, Clock clock) {
    return switch (o.portType()) {
      case "serial" -> RobotAddress.serial(o.port(), 9600).connection(clock);
      case "tcp" -> {
        RobotAddress a = RobotAddress.parse(o.port());
        if (a.isSerial()) {
          throw new IllegalArgumentException("-laserPortType tcp needs -laserPort HOST:PORT");
        }
        yield a.connection(clock);
      }
      default ->
          throw new IllegalArgumentException(
              "laser port type is serial or tcp, not '" + o.portType() + "'");
    };
  }

  /**
   * Makes the laser, adds it to the robot (as a range device), and connects it if the options say
   * so ({@code LaserAutoConnect true} or {@code -connectLaser}).
   *
   * @return false if a laser should have connected and did not ({@link #getFailure()} says why);
   *     true if it connected, or if there is no laser or it should not connect
   */
  public boolean connectLasers() {
    if (!parsed && !parseArgs()) {
      return false;
    }
    LaserOptions o = getOptions();
    try {
      // A real device lives in real time, even when the robot runs on a virtual clock.
      laser = createLaser(o, Clock.system());
    } catch (IllegalArgumentException e) {
      failure = e.getMessage();
      log.error("{}", failure);
      return false;
    }
    if (laser == null) {
      return true;
    }
    if (robot != null) {
      robot.addRangeDevice(laser);
    }
    if (!o.connect()) {
      log.info("{} set up but not connected (give -connectLaser to connect it)", laser.getName());
      return true;
    }
    if (!laser.blockingConnect()) {
      failure = laser.getConnectFailure();
      return false;
    }
    return true;
  }

  /** The laser made by {@link #connectLasers()}, or null. */
  public ArLaser getLaser() {
    return laser;
  }

  /** Why the last step failed, or "". */
  public String getFailure() {
    return failure;
  }
}
