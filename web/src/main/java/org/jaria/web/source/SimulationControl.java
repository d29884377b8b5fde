package org.jaria.web.source;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import org.jaria.sim.SimWorld;
import org.jaria.web.control.ControlCommand;
import org.jaria.web.control.Controls;
import org.jaria.web.model.ClockFrame;

/**
 * Runs, pauses, steps and speeds up a simulated world for the viewers, and says how it runs (for
 * the clock on the page). Goes through {@link SimWorld}'s thread-safe API; never holds the world's
 * lock itself.
 */
public final class SimulationControl implements Controls.Simulation {

  private final SimWorld world;

  @GuardedBy("this")
  private double speedup;

  /**
   * @param world the world (already running in real time, or paused)
   * @param speedup the speed-up it runs at (1: real time; 0: as fast as it can)
   */
  public SimulationControl(SimWorld world, double speedup) {
    this.world = world;
    this.speedup = speedup;
  }

  @Override
  public synchronized void run() {
    if (!world.isRealTime()) {
      world.startRealTime(speedup);
    }
  }

  @Override
  public synchronized void pause() {
    world.stopRealTime();
  }

  @Override
  public synchronized void step(long millis) {
    if (millis <= 0 || millis > ControlCommand.MAX_STEP_MILLIS) {
      throw new IllegalArgumentException(
          "a step is 1.." + ControlCommand.MAX_STEP_MILLIS + " ms, not " + millis);
    }
    if (world.isRealTime()) {
      world.stopRealTime();
    }
    world.advanceMillis(millis);
  }

  @Override
  public synchronized void setSpeedup(double s) {
    if (!(s > 0 && s <= ControlCommand.MAX_SPEEDUP)) {
      throw new IllegalArgumentException(
          "the speed-up is above 0 and at most " + ControlCommand.MAX_SPEEDUP + ", not " + s);
    }
    speedup = s;
    if (world.isRealTime()) {
      world.stopRealTime();
      world.startRealTime(s);
    }
  }

  /** The world's clock as the page shows it. */
  public synchronized ClockFrame clock() {
    return new ClockFrame(world.getClock().nanoTime(), speedup, !world.isRealTime(), true);
  }
}
