package org.jaria.classroom.grading;

import java.time.Duration;
import org.jaria.classroom.link.StudentLink;
import org.jaria.robot.ArRobot;
import org.jaria.sim.client.SimulatedRobot.ProgramResult;

/** Runs a student's sequential program on the simulator and says how it ended. */
public final class Programs {

  /** Real time a program may compute without waiting on the robot's clock before it is stuck. */
  public static final Duration STUCK_AFTER = Duration.ofSeconds(3);

  private Programs() {}

  /** Something a program does with the robot, allowed to be interrupted while it waits. */
  @FunctionalInterface
  public interface Body {
    /** Runs. */
    void run(ArRobot robot) throws InterruptedException;
  }

  /** How the program ended, and the check that says so. */
  public record Ending(ProgramResult result, Check check) {}

  /**
   * Runs the student's program (set up on their side of {@code link}) for at most {@code max} of
   * simulated time.
   *
   * @param points what ending normally is worth
   */
  public static Ending run(StudentLink link, Duration max, int points) {
    ProgramResult r = link.runProgram(max);
    String name = "program ends";
    Check c =
        switch (r) {
          case FINISHED -> Check.pass(name, points, "your program returned");
          case TIMED_OUT ->
              Check.fail(
                  name,
                  points,
                  "your program was still running after "
                      + max.toSeconds()
                      + " s of robot time: does one of your wait loops never end (a condition"
                      + " that never becomes true)?");
          case STUCK ->
              Check.fail(
                  name,
                  points,
                  "your program kept the computer busy without ever waiting on the robot's clock,"
                      + " so simulated time could not pass: wait with"
                      + " robot.getClock().sleepMillis(50) inside every loop (never busy-wait or"
                      + " Thread.sleep)");
          case FAILED -> Check.fail(name, points, "your program threw " + link.programFailure());
        };
    return new Ending(r, c);
  }
}
