package org.jaria.classroom.link;

import org.jaria.classroom.grading.Solutions;

/**
 * The half of an assignment that runs in the student's JVM: it makes the student's object and hooks
 * it to the robot, and answers the grader's questions about what happened in there (for example
 * whether an action threw). It decides nothing: the grade is made in the grader.
 */
public interface StudentSide {

  /**
   * Makes the student's object from {@code ctx.solution()} and hooks it up: adds actions and
   * devices, or sets the program to run with {@link StudentContext#setProgram}.
   *
   * @throws Solutions.SolutionException with a message for the student if the object cannot be made
   */
  void setUp(StudentContext ctx) throws Solutions.SolutionException;

  /** Answers the grader's {@code name} question (or takes the step it names); "" if unknown. */
  default String call(String name) {
    return "";
  }
}
