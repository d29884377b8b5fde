package org.jaria.classroom.grading;

import java.util.Objects;

/**
 * One graded check of a solution: what was checked, how many points it is worth, whether it passed
 * and, above all, a message that tells the student what happened and what to look at.
 *
 * <p>A check can fail on its own (its message is the diagnosis) or be <em>withheld</em>: it earns
 * nothing because of another check's problem ("fix corner 2 first", "earns nothing until the robot
 * reaches corner 1"). A withheld check says so and names the cause; the class statistics count only
 * checks that failed on their own, so one cause is one diagnosis.
 *
 * @param name short name, e.g. "corner 2 reached"
 * @param points what the check is worth
 * @param passed whether it passed
 * @param message what the robot did (and, on a failure, what to fix)
 * @param withheld whether it failed only because of another check's problem (never when passed)
 */
public record Check(String name, int points, boolean passed, String message, boolean withheld) {

  /** Checks and copies. */
  public Check {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(message, "message");
    if (points < 0) {
      throw new IllegalArgumentException("points must be >= 0: " + points);
    }
    if (passed && withheld) {
      throw new IllegalArgumentException("a passed check is not withheld: " + name);
    }
  }

  /** A check that passed or failed on its own. */
  public Check(String name, int points, boolean passed, String message) {
    this(name, points, passed, message, false);
  }

  /** A passed check. */
  public static Check pass(String name, int points, String message) {
    return new Check(name, points, true, message);
  }

  /** A failed check. */
  public static Check fail(String name, int points, String message) {
    return new Check(name, points, false, message);
  }

  /**
   * A check that earns nothing because of another check's problem, which {@code message} names
   * ("your robot did not get this far: fix corner 2 first").
   */
  public static Check withheld(String name, int points, String message) {
    return new Check(name, points, false, message, true);
  }

  /** A check that passed if {@code ok}, with the message for either case. */
  public static Check of(String name, int points, boolean ok, String ifPassed, String ifFailed) {
    return new Check(name, points, ok, ok ? ifPassed : ifFailed);
  }

  /** The points earned: all of them if passed, none otherwise. */
  public int earned() {
    return passed ? points : 0;
  }
}
