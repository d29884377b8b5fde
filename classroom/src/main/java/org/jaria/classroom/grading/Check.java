package org.jaria.classroom.grading;

import java.util.Objects;

/**
 * One graded check of a solution: what was checked, how many points it is worth, whether it passed
 * and, above all, a message that tells the student what happened and what to look at.
 *
 * @param name short name, e.g. "corner 2 reached"
 * @param points what the check is worth
 * @param passed whether it passed
 * @param message what the robot did (and, on a failure, what to fix)
 */
public record Check(String name, int points, boolean passed, String message) {

  /** Checks and copies. */
  public Check {
    Objects.requireNonNull(name, "name");
    Objects.requireNonNull(message, "message");
    if (points < 0) {
      throw new IllegalArgumentException("points must be >= 0: " + points);
    }
  }

  /** A passed check. */
  public static Check pass(String name, int points, String message) {
    return new Check(name, points, true, message);
  }

  /** A failed check. */
  public static Check fail(String name, int points, String message) {
    return new Check(name, points, false, message);
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
