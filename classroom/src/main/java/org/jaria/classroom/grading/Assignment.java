package org.jaria.classroom.grading;

import java.util.List;
import org.jaria.classroom.link.StudentSide;
import org.jaria.classroom.link.StudentStreams;

/**
 * One assignment of the classroom kit: what a solution must be, and how it is graded on the
 * simulator. Grading is deterministic (a seeded world on virtual time), so a solution gets the same
 * grade on every run, on every computer.
 *
 * <p>Assignments come in packs and are found with {@link java.util.ServiceLoader}: a pack (the
 * kit's own four, or a teacher's folder or jar given to {@code jaria grade --pack}) lists its
 * classes in {@code META-INF/services/org.jaria.classroom.grading.Assignment}. Each needs a public
 * constructor without arguments, which both the grader and the student's JVM call.
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
   * The names of the checks a graded run makes, in order, in the language of {@code t}: the
   * gradebook's columns. (A run that could not grade, e.g. one that did not compile, has one check
   * of its own instead, which has no column.)
   */
  List<String> checkNames(Texts t);

  /**
   * The catalogue this assignment's checks speak in {@code lang} ("en" or "es"): the kit's, which a
   * pack extends with its own sentences ({@link Texts#with}).
   */
  default Texts texts(String lang) {
    return Texts.of(lang);
  }

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
    return grade(student, texts("en"));
  }

  /** The half that runs in the student's process: makes their object and hooks it up. */
  StudentSide studentSide();
}
