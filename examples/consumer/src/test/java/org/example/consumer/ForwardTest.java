package org.example.consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import org.jaria.robot.ArRobot;
import org.jaria.sim.SimRobot;
import org.jaria.sim.client.SimulatedRobot;
import org.jaria.sim.client.SimulatedRobot.ProgramResult;
import org.jaria.sim.junit.SimulatedRobotTest;
import org.junit.jupiter.api.Test;

/**
 * The user's program on a simulated robot, on virtual time: a minute of robot time takes
 * milliseconds, and every run gives the same result.
 */
@SimulatedRobotTest(map = "hall", robot = "p3dx-sh", seed = 1)
class ForwardTest {

  @Test
  void drivesOneMetreAndStops(ArRobot robot, SimulatedRobot sim, SimRobot truth) {
    double x0 = truth.getTruePose().x();
    ProgramResult result =
        sim.runProgram(
            r -> {
              try {
                Forward.drive(r, 1000);
              } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
              }
            },
            Duration.ofSeconds(30));
    assertEquals(ProgramResult.FINISHED, result, "the program ends on its own");
    sim.runMillis(1000); // settle
    assertEquals(1000, truth.getTruePose().x() - x0, 50, "the robot really moved 1 m");
    assertEquals(0, robot.getVel(), 1, "and stopped");
  }
}
