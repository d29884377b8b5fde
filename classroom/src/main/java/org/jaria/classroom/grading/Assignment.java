package org.jaria.classroom.grading;

import org.jaria.classroom.link.StudentSide;
import org.jaria.classroom.link.StudentStreams;

/**
 * One assignment of the classroom kit: what a solution must be, and how it is graded on the
 * simulator. Grading is deterministic (a seeded world on virtual time), so a solution gets the same
 * grade on every run, on every computer.
 */
public interface Assignment {

  /** The id used on the command line, e.g. "square". */
  String id();

  /** A one-line title. */
  String title();

  /** The type a solution class must have (an interface to implement or a class to extend). */
  Class<?> solutionType();

  /** The class name the starter file uses, e.g. "Square"; preferred when several classes fit. */
  String solutionClassName();

  /**
   * What a solution must look like, in a sentence a student can act on, e.g. "a public class that
   * implements org.jaria.classroom.RobotProgram and has a public no-argument constructor".
   */
  String solutionShape();

  /** The points a perfect solution earns (the sum of every check's points). */
  int points();

  /**
   * Grades the student whose process is at the other end of {@code student} on the simulator: the
   * world, its ground truth and the checks live here, the student's object lives in their process
   * ({@link #studentSide()}), joined by a {@link org.jaria.classroom.link.StudentLink}. Never
   * throws for a faulty solution: every problem becomes a failed check with a message, in the
   * language of {@code texts}.
   *
   * @throws org.jaria.classroom.link.LinkLost if the student's process stops answering
   */
  Grade grade(StudentStreams student, Texts texts);

  /** {@link #grade(StudentStreams, Texts)} in English. */
  default Grade grade(StudentStreams student) {
    return grade(student, Texts.english());
  }

  /** The half that runs in the student's process: makes their object and hooks it up. */
  StudentSide studentSide();
}
