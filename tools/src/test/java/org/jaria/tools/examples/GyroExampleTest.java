package org.jaria.tools.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.jaria.geom.ArMath;
import org.jaria.input.ArKeyHandler;
import org.jaria.robot.ArRobot;
import org.jaria.sim.RobotOptions;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.jaria.sim.client.SimulatedRobot;
import org.junit.jupiter.api.Test;

/** The thesis's turn-control keys (gyroExample) on a simulated robot with a gyro, lockstep. */
class GyroExampleTest {

  @Test
  void keysTurnAtTheirSpeedsHeadToTheirHeadingsAndSpaceStops() {
    try (SimWorld world = SimWorld.bundled("hall", SimOptions.builder().seed(3).build())) {
      SimRobot r = world.addRobot(RobotOptions.of("p3dx-sh").withGyro(true));
      try (SimulatedRobot sim = SimulatedRobot.connect(world, r);
          ArKeyHandler keys = new ArKeyHandler()) {
        ArRobot robot = sim.robot();
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        new GyroExample.GyroTask(
            robot, keys, new PrintStream(printed, true, StandardCharsets.UTF_8), 10);
        keys.attachKeyHandler(robot, false, null);
        robot.enableMotors();
        sim.runMillis(2000);

        keys.feedKey('3'); // 30 deg/s counter-clockwise
        sim.runMillis(2000);
        assertEquals(30, r.getRotVel(), 1.0, "key 3 turns at 30 deg/s");
        keys.feedKey('w'); // 20 deg/s clockwise
        sim.runMillis(2000);
        assertEquals(-20, r.getRotVel(), 1.0, "key w turns at -20 deg/s");
        keys.feedKey(ArKeyHandler.SPACE);
        sim.runMillis(1500);
        assertEquals(0, r.getRotVel(), 0.5, "space stops");

        double start = robot.getTh();
        for (char k : new char[] {'s', 'd', 'f', 'a'}) {
          double target = "asdf".indexOf(k) * 90.0;
          keys.feedKey(k);
          sim.runMillis(200);
          assertTrue(
              sim.runUntil(robot::isHeadingDone, Duration.ofSeconds(15)),
              "key " + k + " turns to " + target + " (from " + start + ")");
          sim.runMillis(1000);
          assertEquals(0, ArMath.subAngle(robot.getTh(), target), 3.0, "heading after key " + k);
        }
        String out = printed.toString(StandardCharsets.UTF_8);
        assertTrue(out.contains("gyro") && out.contains("mixed"), "prints the headings: " + out);
      }
    }
  }
}
