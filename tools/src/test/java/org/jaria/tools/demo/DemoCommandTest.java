package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import org.jaria.geom.ArPose;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.testing.SocatPty;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The demos through the real command line, each for a couple of seconds against its embedded
 * simulator on TCP (real time: these check the wiring and the output, not the robot's skill — the
 * scenario tests do that on virtual time).
 */
class DemoCommandTest {

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

  @Test
  void wanderPrintsAStatusLineASecondAndStopsAtItsTimeLimit() {
    Run r = jaria("demo", "wander", "--seconds", "2");
    assertEquals(0, r.status(), r.out() + r.err());
    assertTrue(r.out().contains("Simulator: office map"), r.out());
    assertTrue(r.out().contains("t=  1s") && r.out().contains("t=  2s"), r.out());
    assertTrue(r.out().contains("true pose"), r.out());
    assertTrue(
        Thread.getAllStackTraces().keySet().stream()
            .noneMatch(t -> t.getName().equals("demo-status") && t.isAlive()),
        "the status thread was joined");
  }

  @Test
  void gotoReachesTheGivenPoses() {
    Run r = jaria("demo", "goto", "--pose", "600,0", "--pose", "0,0");
    assertEquals(0, r.status(), r.out() + r.err());
    assertTrue(r.out().contains("reached goal 2"), r.out());
    assertTrue(r.out().contains("all goals reached"), r.out());
  }

  @Test
  void wanderDrivesARobotOnASerialPort(@TempDir Path dir) throws Exception {
    // A simulator behind a real pseudo-terminal: the demo opens it as a serial port, exactly as
    // it would open a Pioneer's /dev/ttyS0.
    try (SimWorld world =
        SimWorld.bundled("office", SimOptions.builder().basePort(0).seed(3).build())) {
      SimRobot robot = world.addRobot("p3dx-sh");
      world.listen();
      world.startRealTime(1);
      ArPose start = robot.getTruePose();
      try (SocatPty serial = SocatPty.bridgedToTcp(dir, "127.0.0.1", robot.getPort())) {
        Run r = jaria("demo", "wander", "--remote", serial.a.toString(), "--seconds", "3");
        assertEquals(0, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("t=  2s"), r.out());
      }
      double moved = robot.getTruePose().findDistanceTo(start);
      assertTrue(moved > 300, "the robot drove " + moved + " mm over the serial line");
    }
  }

  @Test
  void aMalformedPoseIsRefusedWithAnExample() {
    Run r = jaria("demo", "goto", "--pose", "here");
    assertEquals(2, r.status());
    assertTrue(r.err().contains("--pose wants X,Y in millimetres"), r.err());
  }

  @Test
  void chaseStartsTheSimulatorAndActsAndPrintsTheBallDistance() {
    Run r = jaria("demo", "chase", "--seconds", "2");
    assertEquals(0, r.status(), r.out() + r.err());
    assertTrue(r.out().contains("channel 1 trained on the red ball"), r.out());
    assertTrue(r.out().contains("ball") && r.out().contains("mm away"), r.out());
  }

  @Test
  void navigateReachesTheFirstGoalOfTheOfficeInLockstep() {
    Run r = jaria("demo", "navigate", "--map", "office", "--goal", "Corridor West");
    assertEquals(0, r.status(), r.out() + r.err());
  }
}
