package org.jaria.classroom.grading;

import java.util.List;
import java.util.stream.Collectors;

/**
 * The checks of one graded solution, in the order they were made.
 *
 * @param assignment the assignment's id
 * @param checks the checks
 */
public record Grade(String assignment, List<Check> checks) {

  /** Copies. */
  public Grade {
    checks = List.copyOf(checks);
  }

  /** Points earned. */
  public int score() {
    return checks.stream().mapToInt(Check::earned).sum();
  }

  /** Points available. */
  public int maxScore() {
    return checks.stream().mapToInt(Check::points).sum();
  }

  /** Whether every check passed. */
  public boolean passed() {
    return !checks.isEmpty() && checks.stream().allMatch(Check::passed);
  }

  /** The failed checks. */
  public List<Check> failures() {
    return checks.stream().filter(c -> !c.passed()).toList();
  }

  /** One line per check, "[PASS] name: message" — for assertion messages and consoles. */
  public String describe() {
    return checks.stream()
        .map(c -> (c.passed() ? "[PASS] " : "[FAIL] ") + c.name() + ": " + c.message())
        .collect(Collectors.joining("\n"));
  }
}
