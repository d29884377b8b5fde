package org.jaria.web.model;

/**
 * The clock the picture was taken by.
 *
 * @param timeNanos the source's time: simulated time for a simulator, the robot's clock otherwise
 * @param speedup how many simulated seconds pass per real second (1: real time; 0: as fast as the
 *     machine can; NaN for a real robot)
 * @param paused whether the simulation is paused
 * @param simulated whether the time is a simulator's
 */
public record ClockFrame(long timeNanos, double speedup, boolean paused, boolean simulated) {

  /** A real robot's clock at {@code nanos}. */
  public static ClockFrame real(long nanos) {
    return new ClockFrame(nanos, Double.NaN, false, false);
  }
}
