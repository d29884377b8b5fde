package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.clock.VirtualClock;
import org.junit.jupiter.api.Test;

/** The run loop runs what it is given, without a robot: a cycle, its waits, and its exit. */
class RunLoopTest {

  /**
   * A cycle that always has input (so the loop never sleeps), is linked for {@code linkedCycles}
   * cycles, and asks the loop to stop after {@code stopAfter}.
   */
  private static final class Counted implements RunLoop.Cycle {
    final AtomicInteger ran = new AtomicInteger();
    final AtomicInteger waited = new AtomicInteger();
    final int linkedCycles;
    final int stopAfter;
    RunLoop loop;

    Counted(int linkedCycles, int stopAfter) {
      this.linkedCycles = linkedCycles;
      this.stopAfter = stopAfter;
    }

    @Override
    public long cycleTimeMs() {
      return 100;
    }

    @Override
    public boolean awaitInput(long start, long cycleNanos) {
      waited.incrementAndGet();
      return true;
    }

    @Override
    public void runOnce() {
      int n = ran.incrementAndGet();
      if (n == 1) {
        // the loop is running: it may not be started a second time
        assertThrows(IllegalStateException.class, () -> loop.run(false));
      }
      if (n == stopAfter) {
        loop.stopRunning();
      }
    }

    @Override
    public boolean linked() {
      return ran.get() < linkedCycles;
    }
  }

  private static RunLoop loop(Counted cycle, AtomicInteger exits) {
    cycle.loop = new RunLoop("test", new VirtualClock(), cycle, exits::incrementAndGet);
    return cycle.loop;
  }

  @Test
  void itStopsWhenTheCycleIsNoLongerLinkedAndRunsTheExitOnce() {
    Counted cycle = new Counted(3, Integer.MAX_VALUE);
    AtomicInteger exits = new AtomicInteger();
    RunLoop loop = loop(cycle, exits);
    loop.run(true);
    assertEquals(3, cycle.ran.get());
    assertEquals(3, cycle.waited.get());
    assertEquals(1, exits.get());
    assertFalse(loop.isRunning());
  }

  @Test
  void aStopRequestEndsTheLoopBeforeTheNextCycle() {
    Counted cycle = new Counted(Integer.MAX_VALUE, 2);
    AtomicInteger exits = new AtomicInteger();
    loop(cycle, exits).run(false);
    assertEquals(2, cycle.ran.get());
    assertEquals(1, exits.get());
  }
}
