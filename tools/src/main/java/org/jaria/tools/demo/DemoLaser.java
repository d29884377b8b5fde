package org.jaria.tools.demo;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.Locale;
import org.jaria.clock.Clock;
import org.jaria.connection.RobotAddress;
import org.jaria.laser.ArLMS2xx;
import org.jaria.laser.ArLaser;
import org.jaria.laser.ArUrg;
import org.jaria.laser.LmsSettings;
import org.jaria.laser.UrgSettings;
import org.jaria.robot.ArRobot;
import org.jaria.sim.devices.DeviceFaults;
import org.jaria.sim.devices.DeviceTcpServer;
import org.jaria.sim.devices.LaserSensor;
import org.jaria.sim.devices.Lms200Emulator;
import org.jaria.sim.devices.UrgEmulator;

/**
 * A demo's laser ({@code --laser TYPE}): on a real robot the device on {@code --laser-port}; with
 * the embedded simulator, the simulated robot's laser presented as a real LMS-200 or URG on a
 * loopback TCP port, so the demo runs the same driver it would on a robot. Once connected the laser
 * is one of the robot's range devices, so the avoidance actions use it beside the sonar.
 */
final class DemoLaser implements AutoCloseable {

  private final ArLaser laser;
  private final DeviceTcpServer emulator;

  /**
   * Makes the laser (not yet connected).
   *
   * @param type lms2xx or urg
   * @param port the laser's port on a real robot (null with the embedded simulator)
   * @param sim the embedded simulator, or null
   * @throws IllegalArgumentException if the type is unknown or a real robot's laser has no port
   */
  DemoLaser(String type, String port, EmbeddedSimulator sim) throws IOException {
    String t = type.toLowerCase(Locale.ROOT);
    laser =
        switch (t) {
          case "lms2xx", "sick" -> new ArLMS2xx("lms2xx_1", LmsSettings.DEFAULT);
          case "urg" -> new ArUrg("urg_1", UrgSettings.DEFAULT);
          default ->
              throw new IllegalArgumentException("--laser is lms2xx or urg, not '" + type + "'");
        };
    if (sim != null) {
      LaserSensor sensor = LaserSensor.of(sim.robot);
      emulator =
          new DeviceTcpServer(
              0,
              (c, i) ->
                  laser instanceof ArUrg
                      ? new UrgEmulator(c, sensor, DeviceFaults.NONE, 100)
                      : new Lms200Emulator(c, sensor, DeviceFaults.NONE, 100));
      laser.setDeviceConnection(
          RobotAddress.tcp("127.0.0.1", emulator.getPort()).connection(Clock.system()));
    } else {
      if (port == null) {
        throw new IllegalArgumentException(
            "with --remote, give the laser's port with --laser-port (e.g. /dev/ttyUSB0)");
      }
      emulator = null;
      laser.setDeviceConnection(RobotAddress.parse(port).connection(Clock.system()));
    }
  }

  /** Mounts the laser as the robot's parameters say, connects it, and adds it to the robot. */
  boolean attach(ArRobot robot, PrintWriter out) {
    var p = robot.getRobotParams();
    laser.setSensorPosition(p.getLaserX(), p.getLaserY(), p.getLaserTh());
    if (!laser.blockingConnect()) {
      out.println("laser: " + laser.getConnectFailure());
      out.flush();
      return false;
    }
    robot.addRangeDevice(laser);
    out.println(
        "laser "
            + laser.getName()
            + " connected on "
            + laser.getDeviceConnection().getPortName()
            + "; avoiding with it");
    out.flush();
    return true;
  }

  /** The closest current laser reading in a sector, mm, or -1 if none. */
  int closest(double startAngle, double endAngle) {
    double r = laser.currentReadingPolar(startAngle, endAngle);
    return r >= laser.getMaxRange() ? -1 : (int) Math.round(r);
  }

  @Override
  public void close() {
    laser.close();
    if (emulator != null) {
      emulator.close();
    }
  }
}
