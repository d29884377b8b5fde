package org.jaria.web.control;

import org.jaria.geom.ArPose;

/**
 * What a viewer may do, when the server allows control: drive a robot, send it to a goal, and run,
 * pause, step or speed up a simulation. A source offers what it can; the rest are absent ({@link
 * #driver()} or {@link #simulation()} null). Implementations are thread-safe: the server calls them
 * from its network threads, never from the robot's cycle.
 *
 * @param driver drives one robot, or null
 * @param simulation runs the simulation, or null
 */
public record Controls(Driver driver, Simulation simulation) {

  /** Nothing can be controlled. */
  public static final Controls NONE = new Controls(null, null);

  /** Drives one robot. */
  public interface Driver {
    /** The robot's name. */
    String robotName();

    /**
     * Drives at these velocities for a moment: the robot stops by itself unless told again within
     * {@link ControlCommand#DRIVE_HOLD_MILLIS} ms (a viewer that goes away cannot leave it
     * driving). Cancels a goal.
     *
     * @param vel mm/s, forward positive
     * @param rotVel deg/s, counter-clockwise positive
     */
    void drive(double vel, double rotVel);

    /**
     * Sends the robot to {@code pose} (in the map frame), heading too if {@code useHeading}.
     *
     * @return whether the robot took the goal (a plan was found)
     */
    boolean goTo(ArPose pose, boolean useHeading);

    /** Stops: no goal, no velocity. */
    void stop();
  }

  /** Runs a simulation. */
  public interface Simulation {
    /** Runs in real time times the speed-up. */
    void run();

    /** Pauses (the world keeps its state). */
    void pause();

    /** Advances a paused world by {@code millis} of simulated time. */
    void step(long millis);

    /**
     * Sets the speed-up (1: real time).
     *
     * @throws IllegalArgumentException if it is not a positive number of at most {@link
     *     ControlCommand#MAX_SPEEDUP}
     */
    void setSpeedup(double speedup);
  }

  /** The capabilities as the page reads them: {@code drive}, {@code goal}, {@code sim}. */
  public String describe() {
    StringBuilder sb = new StringBuilder();
    if (driver != null) {
      sb.append("drive,goal");
    }
    if (simulation != null) {
      sb.append(sb.length() > 0 ? "," : "").append("sim");
    }
    return sb.toString();
  }
}
