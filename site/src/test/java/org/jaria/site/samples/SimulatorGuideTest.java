package org.jaria.site.samples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.junit.SimulatedRobotTest;
import org.junit.jupiter.api.Test;

// tag::test[]
/** A teacher's (or student's) test: a robot on the simulator, on virtual time. */
@SimulatedRobotTest(map = "hall", robot = "p3dx-sh", seed = 7)
class SimulatorGuideTest {

  @Test
  void drivesOneMetreForward(ArRobot robot, SimulatedRobot sim, SimRobot truth) {
    double x0 = truth.getTruePose().x();
    robot.enableMotors();
    robot.move(1000);
    assertTrue(sim.runUntil(robot::isMoveDone, Duration.ofSeconds(10)), "the move ends");
    sim.runMillis(1000); // settle
    assertEquals(1000, truth.getTruePose().x() - x0, 50, "the robot really moved 1 m");
  }
}
// end::test[]
