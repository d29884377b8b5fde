package org.jaria.sim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArLMS2xx;
import org.jaria.laser.ArLaser;
import org.jaria.laser.ArLaserConnector;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotModels;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.testing.SocatPty;
import org.jaria.util.ArArgumentParser;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An ARIA-style program's laser set-up: the robot's parameters (p3dx-sh: an LMS-200, connect at
 * start-up) plus {@code -laserPort}, against an LMS-200 emulator on a pty.
 */
class LaserConnectorTest {

  @TempDir Path dir;

  @Test
  void theRobotsLaserConnectsFromItsParametersAndTheCommandLine() throws Exception {
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(3000, -2000, 3000, 2000), new ArLineSegment(-3000, 2000, 3000, 2000));
    try (SimWorld world = SimWorld.ofLines(walls, ArPose.ORIGIN, SimOptions.defaults())) {
      SimRobot simRobot =
          world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withStartPose(ArPose.ORIGIN));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, simRobot);
          SocatPty pty = new SocatPty(dir);
          Lms200Emulator lms =
              Lms200Emulator.start(
                  new ArSerialConnection(pty.b.toString(), 9600, Clock.system()),
                  LaserSensor.of(simRobot),
                  DeviceFaults.NONE,
                  20)) {
        ArRobot robot = sim.robot();
        ArArgumentParser parser = new ArArgumentParser(new String[] {"-lp", pty.a.toString()});
        ArLaserConnector connector = new ArLaserConnector(parser, robot);
        assertTrue(connector.parseArgs());
        assertTrue(connector.connectLasers(), connector.getFailure());
        ArLaser laser = connector.getLaser();
        try {
          assertInstanceOf(ArLMS2xx.class, laser);
          assertTrue(laser.isConnected(), "LaserAutoConnect true in p3dx-sh.p");
          assertSame(laser, robot.findRangeDevice(laser.getName()), "a range device of the robot");
          assertEquals(robot.getRobotParams().getLaserX(), laser.getSensorPosition().x());
          assertTrue(laser.waitForScans(2, 20_000));
          // The emulator counts a scan once its write returned, so the last one received may not be
          // counted yet.
          assertTrue(lms.getScansSent() >= 1);
          // From the robot's centre: the wall ahead at 3 m, the wall on the left at 2 m. The
          // simulator mounts the laser where MobileSim does (the turning centre), the client
          // believes p3dx-sh.p's LaserX, so readings ahead are off by the difference, as they are
          // for an ARIA program on MobileSim.
          double mountError =
              robot.getRobotParams().getLaserX()
                  - RobotModels.mobileSimLaserMount("p3dx-sh").orElseThrow().x();
          assertEquals(3000 + mountError, laser.currentReadingPolar(-2, 2), 2.0);
          assertEquals(2000, laser.currentReadingPolar(85, 95), 2.0);
          assertEquals(2000, laser.currentReadingBox(0, 1500, 1000, 2500), 2.0);
        } finally {
          laser.disconnect();
        }
        assertFalse(laser.isConnected());
      }
    }
  }
}
