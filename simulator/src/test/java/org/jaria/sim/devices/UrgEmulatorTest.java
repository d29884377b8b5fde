package org.jaria.sim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.ArTcpConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArUrg;
import org.jaria.laser.UrgParams;
import org.jaria.laser.UrgSettings;
import org.jaria.range.LaserScan;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.testing.SocatPty;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The URG driver against a simulated laser presented as a URG-04LX on a pty or a TCP port. */
class UrgEmulatorTest {

  private static final long PATIENCE_MS = 20_000;

  @TempDir Path dir;
  private SimWorld world;
  private SimRobot robot;

  @BeforeEach
  void world() {
    // A 4 m x 3 m room (inside the URG-04LX's 5.6 m), the robot at its centre facing +x.
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-2000, -1500, 2000, -1500),
            new ArLineSegment(2000, -1500, 2000, 1500),
            new ArLineSegment(2000, 1500, -2000, 1500),
            new ArLineSegment(-2000, 1500, -2000, -1500));
    world = SimWorld.ofLines(walls, ArPose.ORIGIN, SimOptions.defaults());
    robot = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withStartPose(ArPose.ORIGIN));
  }

  @AfterEach
  void close() {
    world.close();
  }

  private double mountX() {
    return robot.getModel().getLaserX();
  }

  /** The reading nearest {@code angle}. */
  private static double near(LaserScan s, double angle) {
    int best = 0;
    for (int i = 0; i < s.size(); i++) {
      if (Math.abs(s.getAngle(i) - angle) < Math.abs(s.getAngle(best) - angle)) {
        best = i;
      }
    }
    assertTrue(Math.abs(s.getAngle(best) - angle) < 0.6, "a reading near " + angle);
    return s.getRange(best);
  }

  @Test
  void connectsThroughAPtyAndReadsTheWorld() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device =
            new ArSerialConnection(pty.b.toString(), 19200, Clock.system());
        UrgEmulator urg = UrgEmulator.start(device, LaserSensor.of(robot), DeviceFaults.NONE, 20);
        ArUrg laser = new ArUrg("urg", new UrgSettings(-90, 90, 1, 19200, 115200))) {
      ArSerialConnection port = new ArSerialConnection(pty.a.toString(), 19200, Clock.system());
      laser.setDeviceConnection(port);
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertEquals(115200, port.getBaud(), "SS switched the rate");
      assertEquals(115200, device.getBaud());
      assertEquals(UrgParams.URG_04LX, laser.getParams());
      assertEquals("SCIP 2.0", laser.getVersion().get("PROT"));
      assertEquals(5600, laser.getMaxRange());
      assertTrue(laser.waitForScans(3, PATIENCE_MS));
      // The emulator counts a scan once its write returned, so the last one received may not be
      // counted yet.
      assertTrue(urg.getScansSent() >= 2);
      LaserScan s = laser.getLaserScan();
      assertEquals(513, s.size(), "steps 128..640");
      assertEquals(-90, s.getAngle(0), 1e-9);
      assertEquals(2000 - mountX(), near(s, 0), 1.0);
      assertEquals(1500, near(s, 90), 1.0);
      assertEquals(0, laser.getDropCounters().total());
    }
  }

  @Test
  void clusteredReadingsAndLostBytes() throws Exception {
    DeviceFaults faults = DeviceFaults.NONE.withDropEveryNthByte(700).withAnswerDelayMs(100);
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device =
            new ArSerialConnection(pty.b.toString(), 19200, Clock.system());
        UrgEmulator urg = UrgEmulator.start(device, LaserSensor.of(robot), faults, 20);
        ArUrg laser = new ArUrg("urg", new UrgSettings(-45, 45, 3, 19200, 19200))) {
      laser.setDeviceConnection(new ArSerialConnection(pty.a.toString(), 19200, Clock.system()));
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertTrue(laser.waitForScans(5, PATIENCE_MS), "scans keep coming despite lost bytes");
      assertTrue(laser.getDropCounters().total() > 0, "damaged scans were dropped");
      LaserScan s = laser.getLaserScan();
      assertEquals((512 - 256) / 3 + 1, s.size());
      assertEquals(2000 - mountX(), near(s, 0), 1.0);
      assertTrue(urg.isRunning());
    }
  }

  @Test
  void anUnpluggedUrgIsReportedAndReconnectsOverTcp() throws Exception {
    try (DeviceTcpServer server =
            new DeviceTcpServer(
                0,
                (c, i) ->
                    new UrgEmulator(
                        c,
                        LaserSensor.of(robot),
                        i == 0 ? DeviceFaults.NONE.withUnplugAfterScans(2) : DeviceFaults.NONE,
                        20));
        ArUrg laser = new ArUrg()) {
      laser.setConnectionTimeoutMs(1000);
      laser.setDeviceConnection(new ArTcpConnection("127.0.0.1", server.getPort()));
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertTrue(laser.waitForDisconnect(PATIENCE_MS), "lost after the unplug");
      assertEquals(2, laser.getScanCount(), "the half scan was not taken");
      assertTrue(laser.getConnectFailure().contains("lost"), laser.getConnectFailure());
      assertTrue(laser.blockingConnect(), "reconnects: " + laser.getConnectFailure());
      assertTrue(laser.waitForScans(5, PATIENCE_MS), "scans resume");
    }
  }

  @Test
  void silenceOnThePortFailsWithAClearMessage() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArUrg laser = new ArUrg()) {
      laser.setAnswerTimeoutMs(200);
      laser.setDeviceConnection(new ArSerialConnection(pty.a.toString(), 19200, Clock.system()));
      assertFalse(laser.blockingConnect());
      assertTrue(
          laser.getConnectFailure().contains("no answer to SCIP2.0"), laser.getConnectFailure());
    }
  }
}
