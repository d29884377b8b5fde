package org.jaria.tools.laser;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import org.jaria.clock.Clock;
import org.jaria.connection.ArSerialConnection;
import org.jaria.geom.ArLineSegment;
import org.jaria.geom.ArPose;
import org.jaria.range.LaserScan;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.devices.DeviceFaults;
import org.jaria.sim.devices.LaserSensor;
import org.jaria.sim.devices.Lms200Emulator;
import org.jaria.sim.devices.UrgEmulator;
import org.jaria.testing.SocatPty;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code jaria laser} reading the simulator's LMS-200 and URG through a pseudo-terminal. */
class LaserCommandTest {

  @TempDir Path dir;

  private record Run(int status, String out, String err) {}

  private static Run jaria(String... args) {
    CommandLine cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(err, true));
    int status = cli.execute(args);
    return new Run(status, out.toString(), err.toString());
  }

  private static SimWorld room() {
    List<ArLineSegment> walls =
        List.of(
            new ArLineSegment(2500, -2000, 2500, 2000), new ArLineSegment(-2500, 1500, 2500, 1500));
    return SimWorld.ofLines(walls, ArPose.ORIGIN, SimOptions.defaults());
  }

  private static SimRobot robot(SimWorld w) {
    return w.addRobot(RobotOptions.of("p3dx-sh").withLaser(true).withStartPose(ArPose.ORIGIN));
  }

  @Test
  void readsTheSimulatorsLms200ThroughAPty() throws Exception {
    try (SimWorld w = room();
        SocatPty pty = new SocatPty(dir);
        Lms200Emulator lms =
            Lms200Emulator.start(
                new ArSerialConnection(pty.b.toString(), 9600, Clock.system()),
                LaserSensor.of(robot(w)),
                DeviceFaults.NONE,
                20)) {
      Run r = jaria("laser", "--port", pty.a.toString(), "--type", "lms2xx", "--scans", "3");
      assertEquals(0, r.status(), r.err());
      assertTrue(r.out().contains("connected"), r.out());
      double ahead = 2500 - w.getRobot(0).getModel().getLaserX();
      assertTrue(
          r.out().contains("scan 3: 181 readings")
              && r.out().contains(String.format(java.util.Locale.ROOT, "ahead %.0f mm", ahead)),
          r.out());
      assertTrue(r.out().contains("3 scans shown, "), r.out());
      assertTrue(r.out().contains("received; dropped 0 "), r.out());
      // The emulator counts a scan once its write returned, so the last one received may not be
      // counted yet.
      assertTrue(lms.getScansSent() >= 2);
    }
  }

  @Test
  void readsTheSimulatorsUrgThroughAPty() throws Exception {
    try (SimWorld w = room();
        SocatPty pty = new SocatPty(dir);
        UrgEmulator urg =
            UrgEmulator.start(
                new ArSerialConnection(pty.b.toString(), 19200, Clock.system()),
                LaserSensor.of(robot(w)),
                DeviceFaults.NONE,
                20)) {
      Run r = jaria("laser", "-p", pty.a.toString(), "-t", "urg", "-b", "115200", "-n", "2");
      assertEquals(0, r.status(), r.err());
      assertTrue(r.out().contains("scan 2: 513 readings"), r.out());
      assertTrue(r.out().contains("URG-04LX"), r.out());
      assertTrue(urg.getScansSent() >= 1);
    }
  }

  @Test
  void theEmulateSubcommandServesTheReader() throws Exception {
    try (SocatPty pty = new SocatPty(dir)) {
      Run[] served = new Run[1];
      Thread emulator =
          new Thread(
              () ->
                  served[0] =
                      jaria(
                          "laser",
                          "emulate",
                          "--type",
                          "urg",
                          "--device",
                          pty.b.toString(),
                          "--period",
                          "20"),
              "test-emulate");
      emulator.start();
      // The reader retries its first request until the emulator answers; no waiting needed here.
      Run r = jaria("laser", "--port", pty.a.toString(), "--type", "urg", "--scans", "2");
      emulator.interrupt();
      emulator.join(20_000);
      assertEquals(0, r.status(), r.err());
      assertTrue(r.out().contains("scan 2: 513 readings"), r.out());
    }
  }

  @Test
  void mistakesGetAClearMessage() throws Exception {
    Run r = jaria("laser", "--type", "lms2xx");
    assertEquals(2, r.status());
    assertTrue(r.err().contains("give the laser's port with --port"), r.err());
    r = jaria("laser", "--port", "/dev/x", "--type", "lms5xx");
    assertEquals(2, r.status());
    assertTrue(r.err().contains("--type is lms2xx or urg"), r.err());
    try (SocatPty pty = new SocatPty(dir)) {
      r = jaria("laser", "--port", pty.a.toString(), "--type", "urg", "--timeout", "300");
      assertEquals(1, r.status());
      assertTrue(r.err().contains("could not connect"), r.err());
    }
  }

  @Test
  void aSummaryLineSaysWhatMatters() {
    LaserScan s =
        LaserScan.evenlySpaced(ArPose.ORIGIN, -90, 90, new double[] {1000, 2500, 32000}, 32000);
    assertEquals(
        "scan 7: 3 readings, 2 echoes, closest 1000 mm at -90.0°, ahead 2500 mm, 4.5 Hz",
        ScanSummary.line(7, s, 4.5));
  }
}
