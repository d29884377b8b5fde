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
  public record Ending(ProgramResult result, Check check) {

    /** Whether the program returned by itself. */
    public boolean finished() {
      return result == ProgramResult.FINISHED;
    }

    /**
     * {@code c} as it stands if the program finished or {@code c} passed; otherwise {@code c}
     * withheld: it was not judged, because the program did not end by itself (which {@link #check}
     * already diagnoses), so the student reads one diagnosis for one cause.
     */
    public Check judged(Check c, Texts t) {
      if (finished() || c.passed()) {
        return c;
      }
      return Check.withheld(c.name(), c.points(), notJudged(t));
    }

    /** "not judged: your program ... (see 'program ends')", in {@code t}'s language. */
    public String notJudged(Texts t) {
      String why =
          switch (result) {
            case STUCK -> t.get("program.why.stuck");
            case TIMED_OUT -> t.get("program.why.timedOut");
            case FAILED, FINISHED -> t.get("program.why.failed");
          };
      return t.get("program.notJudged", why, check.name());
    }
  }

  /**
   * Runs the student's program (set up on their side of {@code link}) for at most {@code max} of
   * simulated time.
   *
   * @param points what ending normally is worth
   * @param t the language of the check
   */
  public static Ending run(StudentLink link, Duration max, int points, Texts t) {
    ProgramResult r = link.runProgram(max);
    String name = t.get("program.name");
    Check c =
        switch (r) {
          case FINISHED -> Check.pass(name, points, t.get("program.finished"));
          case TIMED_OUT -> Check.fail(name, points, t.get("program.timedOut", max.toSeconds()));
          case STUCK -> Check.fail(name, points, t.get("program.stuck"));
          case FAILED -> Check.fail(name, points, t.get("program.failed", link.programFailure()));
        };
    return new Ending(r, c);
  }
}
