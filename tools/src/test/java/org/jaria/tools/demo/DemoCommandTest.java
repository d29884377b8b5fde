package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArActionAvoidFront;
import org.jaria.action.ArActionBumpers;
import org.jaria.action.ArActionConstantVelocity;
import org.jaria.action.ArActionStallRecover;
import org.jaria.geom.ArPose;
import org.jaria.range.ArSonarDevice;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.testing.SocatPty;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The demos through the real command line, each for a couple of seconds against its embedded
 * simulator on TCP (real time: these check the wiring and the output, not the robot's skill — the
 * scenario tests do that on virtual time).
 */
@Tag("slow")
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
    assertTrue(r.out().contains("3 crates put in its way"), r.out());
    assertTrue(r.out().contains("'pose' is where the robot believes it is"), r.out());
    assertTrue(r.out().contains("Stops by itself after 2 s"), r.out());
    assertTrue(
        Thread.getAllStackTraces().keySet().stream()
            .noneMatch(t -> t.getName().equals("demo-status") && t.isAlive()),
        "the status thread was joined");
  }

  /**
   * The default demo's 30 s on virtual time: the crates are in the robot's way, and the wander
   * program's actions turn it away from them (the reporter prints those turns) without it ever
   * stalling against one.
   */
  @Test
  void theDefaultDemoTurnsAwayFromTheCratesInItsWay() {
    try (SimWorld world = SimWorld.bundled("office", SimOptions.builder().seed(1).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      ArPose start = r.getTruePose();
      List<ObstaclesAhead.Crate> crates = ObstaclesAhead.place(world, start);
      ObstaclesAhead.Crate first = crates.get(0);
      assertTrue(
          Math.abs(first.y() - start.y()) - first.across() / 2 - 190 < 100,
          "the first crate comes within 10 cm of the robot's side (a P3-DX is 380 mm wide): "
              + first);
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r)) {
        ArRobot robot = sim.robot();
        robot.addRangeDevice(new ArSonarDevice());
        robot.enableMotors();
        addWanderActions(robot);
        TurnReporter turns = new TurnReporter();
        List<String> lines = new ArrayList<>();
        int stalledCycles = 0;
        double furthest = 0;
        for (int tenth = 1; tenth <= 300; tenth++) {
          sim.runMillis(100);
          String l =
              turns.update(
                  tenth / 10.0,
                  robot.getRotVel(),
                  robot.getClosestSonarRange(0, 90),
                  robot.getClosestSonarRange(-90, 0));
          if (l != null) {
            lines.add(l);
          }
          stalledCycles += r.isStalled() ? 1 : 0;
          furthest = Math.max(furthest, r.getTruePose().x() - start.x()); // the corridor runs east
        }
        assertTrue(lines.size() >= 2, "it turned away from things: " + lines);
        assertEquals(0, stalledCycles, "never pushed against a crate or a wall: " + lines);
        assertTrue(
            furthest > first.x() - start.x(),
            "it got past the first crate (" + furthest + " mm along the corridor): " + lines);
      }
    }
  }

  /**
   * The five actions {@link org.jaria.tools.examples.GotoActionExample} adds, with its priorities
   * and settings (that program is quoted line by line next to the thesis's C++, so its actions stay
   * inline there).
   */
  private static void addWanderActions(ArRobot robot) {
    robot.addAction(new ArActionStallRecover(), 100);
    robot.addAction(new ArActionBumpers(), 75);
    robot.addAction(new ArActionAvoidFront("Avoid Front Near", 225, 0), 50);
    robot.addAction(new ArActionAvoidFront(), 49);
    robot.addAction(new ArActionConstantVelocity("Constant Velocity", 400), 25);
  }

  @Test
  void gyroDemoPressesItsKeysWithoutAKeyConflict() {
    PrintStream realErr = System.err;
    ByteArrayOutputStream logged = new ByteArrayOutputStream();
    System.setErr(new PrintStream(logged, true, StandardCharsets.UTF_8)); // slf4j-simple's output
    Run r;
    try {
      r = jaria("demo", "gyro", "--seconds", "5");
    } finally {
      System.setErr(realErr);
    }
    String log = logged.toString(StandardCharsets.UTF_8);
    assertEquals(0, r.status(), r.out() + r.err() + log);
    assertTrue(r.out().contains("gyro"), r.out());
    assertTrue(!log.contains("keydrive will not work"), log);
    // It says that it presses the keys itself, not that the user may.
    assertTrue(r.out().contains("The demo presses the keys itself"), r.out());
    assertTrue(!r.out().contains("This program lets you drive"), r.out());
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
    PrintStream realOut = System.out;
    ByteArrayOutputStream printed = new ByteArrayOutputStream();
    System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8)); // the program's own
    Run r;
    try {
      r = jaria("demo", "chase", "--seconds", "2");
    } finally {
      System.setOut(realOut);
    }
    String program = printed.toString(StandardCharsets.UTF_8);
    assertEquals(0, r.status(), r.out() + r.err());
    assertTrue(r.out().contains("channel 1 trained on the red ball"), r.out());
    assertTrue(r.out().contains("ball") && r.out().contains("mm away"), r.out());
    // The channel is trained and no key is read: the program says so, not "train ACTS".
    assertTrue(program.contains("trained on it already"), program);
    assertTrue(program.contains("The keyboard is not read"), program);
    assertTrue(!program.contains("Train ACTS"), program);
  }

  @Test
  void navigateReachesTheFirstGoalOfTheOfficeInLockstep() {
    Run r = jaria("demo", "navigate", "--map", "office", "--goal", "Corridor West");
    assertEquals(0, r.status(), r.out() + r.err());
  }
}
