package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The checks of one graded solution, in the order they were made, and the grader's notes about the
 * grading itself (what the robot link refused, say), which earn or cost nothing by themselves.
 *
 * @param assignment the assignment's id
 * @param checks the checks
 * @param notes what the grader has to say besides the checks, one sentence each
 */
public record Grade(String assignment, List<Check> checks, List<String> notes) {

  /** Copies. */
  public Grade {
    checks = List.copyOf(checks);
    notes = List.copyOf(notes);
  }

  /** A grade without notes. */
  public Grade(String assignment, List<Check> checks) {
    this(assignment, checks, List.of());
  }

  /** This grade with {@code note} added. */
  public Grade withNote(String note) {
    List<String> n = new ArrayList<>(notes);
    n.add(note);
    return new Grade(assignment, checks, n);
  }

  /** This grade with other checks, and the same notes. */
  public Grade withChecks(List<Check> other) {
    return new Grade(assignment, other, notes);
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

  /** The failed checks (withheld ones included). */
  public List<Check> failures() {
    return checks.stream().filter(c -> !c.passed()).toList();
  }

  /** One line per check, "[PASS] name: message", then the notes — for assertions and consoles. */
  public String describe() {
    String s =
        checks.stream()
            .map(c -> (c.passed() ? "[PASS] " : "[FAIL] ") + c.name() + ": " + c.message())
            .collect(Collectors.joining("\n"));
    for (String n : notes) {
      s += "\nNote: " + n;
    }
    return s;
  }
}
