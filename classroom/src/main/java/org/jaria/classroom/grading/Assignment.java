package org.jaria.classroom.grading;

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
   * Grades {@code solution} (a class of {@link #solutionType()}) on the simulator. Never throws for
   * a faulty solution: every problem becomes a failed check with a message.
   */
  Grade grade(Class<?> solution);
}
