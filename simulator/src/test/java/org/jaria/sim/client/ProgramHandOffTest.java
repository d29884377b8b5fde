package org.jaria.sim.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.jaria.clock.Clock;
import org.junit.jupiter.api.Test;

/** How {@link SimulatedRobot#runProgram} hands control between a program and the world. */
class ProgramHandOffTest {

  /** Clock times a program sees when it sleeps 50 ms ten times. */
  private static List<Long> sleepTenTimes(SimulatedRobot sim) {
    List<Long> seen = new ArrayList<>();
    assertEquals(
        SimulatedRobot.ProgramResult.FINISHED,
        sim.runProgram(
            robot -> {
              Clock c = robot.getClock();
              for (int i = 0; i < 10; i++) {
                seen.add(c.nanoTime());
                try {
                  c.sleepMillis(50);
                } catch (InterruptedException e) {
                  Thread.currentThread().interrupt();
                  return;
                }
              }
              seen.add(c.nanoTime());
            },
            Duration.ofSeconds(10)));
    return seen;
  }

  @Test
  void theWorldMovesOnlyWhileTheProgramWaitsAndNeverSkipsItsWakeUp() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 3)) {
      List<Long> seen = sleepTenTimes(sim);
      assertEquals(11, seen.size());
      for (int i = 1; i < seen.size(); i++) {
        assertEquals(
            50_000_000L, seen.get(i) - seen.get(i - 1), "woke exactly on time at sleep " + i);
      }
      assertEquals(seen.get(10), sim.world().getClock().nanoTime(), "no tick ran after the end");
    }
  }

  @Test
  void aStuckProgramIsInterruptedAndJoinedBeforeRunProgramReturns() {
    try (SimulatedRobot sim = SimulatedRobot.start("hall", "p3dx-sh", 3)) {
      sim.setStuckTimeout(Duration.ofMillis(200));
      AtomicBoolean cleanedUp = new AtomicBoolean();
      AtomicReference<Thread> programThread = new AtomicReference<>();
      long before = sim.world().getClock().nanoTime();
      assertEquals(
          SimulatedRobot.ProgramResult.STUCK,
          sim.runProgram(
              robot -> {
                programThread.set(Thread.currentThread());
                try {
                  while (!Thread.currentThread().isInterrupted()) {
                    Thread.onSpinWait(); // busy, never waits on the robot's clock
                  }
                } finally {
                  cleanedUp.set(true);
                }
              },
              Duration.ofSeconds(10)));
      assertTrue(cleanedUp.get(), "the program had ended when runProgram returned");
      assertFalse(programThread.get().isAlive(), "its thread was joined");
      assertEquals(before, sim.world().getClock().nanoTime(), "a stuck program gets no time");
    }
  }
}
