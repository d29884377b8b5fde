package org.jaria.sim.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.jaria.geom.ArPose;
import org.jaria.robot.ArRobot;
import org.junit.jupiter.api.Test;

/** Sequential programs (command, wait, command) on virtual time. */
class SequentialProgramTest {

  /** A square of one-metre sides with motion commands, waiting on the robot's clock. */
  static void driveSquare(ArRobot robot) {
    try {
      robot.enableMotors();
      for (int side = 0; side < 4; side++) {
        robot.move(1000);
        while (!robot.isMoveDone()) {
          robot.getClock().sleepMillis(50);
        }
        robot.setDeltaHeading(90);
        while (!robot.isHeadingDone()) {
          robot.getClock().sleepMillis(50);
        }
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  @Test
  void aSquareProgramRunsOnVirtualTimeAndEndsWhereItStarted() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 2)) {
      ArPose start = sim.sim().getTruePose();
      long t0 = sim.world().getClock().nanoTime();
      assertEquals(
          SimulatedRobot.ProgramResult.FINISHED,
          sim.runProgram(SequentialProgramTest::driveSquare, Duration.ofMinutes(2)));
      double seconds = (sim.world().getClock().nanoTime() - t0) / 1e9;
      assertTrue(seconds > 10 && seconds < 60, "took " + seconds + " s of robot time");
      assertTrue(sim.sim().getTruePose().findDistanceTo(start) < 150, "back near the start");
    }
  }

  @Test
  void aProgramThatNeverWaitsIsReportedStuckAndOneThatThrowsFailed() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 2)) {
      sim.setStuckTimeout(Duration.ofMillis(500));
      assertEquals(
          SimulatedRobot.ProgramResult.STUCK,
          sim.runProgram(
              robot -> {
                // Waits for time to pass by watching the clock, never sleeping on it: on virtual
                // time the world cannot move on.
                long until = robot.getClock().nanoTime() + 1_000_000_000L;
                while (robot.getClock().nanoTime() < until) {
                  if (Thread.currentThread().isInterrupted()) {
                    return;
                  }
                  Thread.onSpinWait();
                }
              },
              Duration.ofSeconds(10)));
      assertEquals(
          SimulatedRobot.ProgramResult.FAILED,
          sim.runProgram(
              robot -> {
                throw new IllegalStateException("student bug");
              },
              Duration.ofSeconds(10)));
      assertEquals("student bug", sim.lastProgramFailure().getMessage());
    }
  }

  @Test
  void aProgramThatWaitsForeverTimesOut() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 2)) {
      assertEquals(
          SimulatedRobot.ProgramResult.TIMED_OUT,
          sim.runProgram(
              robot -> {
                try {
                  robot.getClock().sleepMillis(600_000);
                } catch (InterruptedException e) {
                  Thread.currentThread().interrupt();
                }
              },
              Duration.ofSeconds(20)));
    }
  }
}
