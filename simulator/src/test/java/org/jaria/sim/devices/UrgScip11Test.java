package org.jaria.sim.devices;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.connection.PipeConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.laser.ArUrg;
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

/** SCIP 1.1, ARIA's ArUrg protocol: the emulator's bytes, and the driver through a pty. */
class UrgScip11Test {

  private static final long PATIENCE_MS = 20_000;

  @TempDir Path dir;
  private SimWorld world;
  private SimRobot robot;

  @BeforeEach
  void world() {
    // A 3 m x 3 m room: every wall within the 4095 mm two characters carry.
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(-1500, -1500, 1500, -1500),
            new ArLineSegment(1500, -1500, 1500, 1500),
            new ArLineSegment(1500, 1500, -1500, 1500),
            new ArLineSegment(-1500, 1500, -1500, -1500));
    world = SimWorld.ofLines(walls, ArPose.ORIGIN, SimOptions.defaults());
    robot = world.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withStartPose(ArPose.ORIGIN));
  }

  @AfterEach
  void close() {
    world.close();
  }

  /** Writes {@code request} and reads the whole answer (up to its empty line). */
  private static String exchange(PipeConnection c, String request) throws Exception {
    byte[] out = request.getBytes(StandardCharsets.US_ASCII);
    c.write(out, 0, out.length);
    StringBuilder sb = new StringBuilder();
    byte[] buf = new byte[512];
    while (!sb.toString().endsWith("\n\n")) {
      int n = c.read(buf, 0, buf.length, PATIENCE_MS);
      assertTrue(n > 0, "an answer to " + request.strip() + ", got so far: " + sb);
      sb.append(new String(buf, 0, n, StandardCharsets.US_ASCII));
    }
    return sb.toString();
  }

  @Test
  void theEmulatorAnswersAsAScip11Urg() throws Exception {
    PipeConnection.Pair pipe = PipeConnection.pair(Clock.system());
    pipe.a().open();
    pipe.b().open();
    try (UrgEmulator urg =
        UrgEmulator.startScip11(pipe.b(), LaserSensor.of(robot), DeviceFaults.NONE, 20)) {
      String v = exchange(pipe.a(), "V\n");
      assertTrue(v.startsWith("V\n0\nVEND:Hokuyo Automatic Co.,Ltd.\n"), v);
      assertTrue(v.contains("\nPROT:SCIP 1.1\n"), v);
      // straight ahead only: step 384, one reading of two characters
      String g = exchange(pipe.a(), "G38438401\n");
      assertEquals(16, g.length(), g); // echo, status, one data line, empty line
      assertTrue(g.startsWith("G38438401\n0\n"), g);
      int mm = ((g.charAt(12) - 0x30) << 6) | (g.charAt(13) - 0x30);
      assertEquals(1500 - robot.getModel().getLaserX(), mm, 1.0, "the wall ahead");
      assertEquals("G90090001\n1\n\n", exchange(pipe.a(), "G90090001\n"), "beyond step 725");
      assertEquals("MD\nE\n\n", exchange(pipe.a(), "MD\n"), "unknown in 1.1");
      assertEquals("SCIP2.0\n0\n\n", exchange(pipe.a(), "SCIP2.0\n"));
      assertTrue(exchange(pipe.a(), "VV\n").contains("PROT:SCIP 2.0;"), "now speaks 2.0");
      assertTrue(urg.isRunning());
    }
  }

  @Test
  void ariasScip11DriverReadsScansThroughAPty() throws Exception {
    try (SocatPty pty = new SocatPty(dir);
        ArSerialConnection device =
            new ArSerialConnection(pty.b.toString(), 19200, Clock.system());
        UrgEmulator urg =
            UrgEmulator.startScip11(device, LaserSensor.of(robot), DeviceFaults.NONE, 20);
        ArUrg laser = new ArUrg("urg", new UrgSettings(-90, 90, 1, 19200, 115200))) {
      // tag::scip11[]
      laser.setProtocol(ArUrg.Protocol.SCIP_1_1); // ARIA's ArUrg: V, S, then a G per scan
      ArSerialConnection port = new ArSerialConnection(pty.a.toString(), 19200, Clock.system());
      laser.setDeviceConnection(port);
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      // end::scip11[]
      assertEquals(115200, port.getBaud(), "S switched the rate");
      assertEquals(115200, device.getBaud());
      assertEquals("SCIP 1.1", laser.getVersion().get("PROT"));
      assertEquals(4095, laser.getMaxRange());
      assertTrue(laser.waitForScans(5, PATIENCE_MS), "a G per scan, again and again");
      LaserScan s = laser.getLaserScan();
      assertEquals(513, s.size(), "steps 128..640");
      assertEquals(-90, s.getAngle(0), 1e-9);
      double ahead = s.getRange(256);
      assertEquals(1500 - robot.getModel().getLaserX(), ahead, 1.0);
      assertEquals(1500, s.getRange(512), 1.0, "the wall to the left");
      assertEquals(0, laser.getDropCounters().total());
      assertTrue(urg.isRunning());
    }
  }

  @Test
  void theScip20DriverSwitchesAUrgThatStartsInScip11() throws Exception {
    PipeConnection.Pair pipe = PipeConnection.pair(Clock.system());
    pipe.a().open();
    pipe.b().open();
    try (UrgEmulator urg =
            UrgEmulator.startScip11(pipe.b(), LaserSensor.of(robot), DeviceFaults.NONE, 20);
        ArUrg laser = new ArUrg()) {
      laser.setDeviceConnection(pipe.a());
      assertTrue(laser.blockingConnect(), laser.getConnectFailure());
      assertEquals("SCIP 2.0", laser.getVersion().get("PROT"), "SCIP2.0 switched it");
      assertTrue(laser.waitForScans(3, PATIENCE_MS));
      assertTrue(urg.getScansSent() >= 2, "MD streams");
    }
  }
}
