package org.jaria.classroom.grading;

import java.nio.file.Path;
import java.util.List;

/**
 * The main class of a grading JVM: grades one student's compiled classes and writes the grade to a
 * file. One JVM per student keeps a submission that hangs, loops, calls System.exit or exhausts
 * memory from touching the others: the {@link Grader} just kills it after the time limit.
 */
public final class GradeChild {

  private GradeChild() {}

  /** Arguments: assignment id, folder of compiled classes, grade file to write. */
  public static void main(String[] args) throws Exception {
    if (args.length != 3) {
      System.err.println("usage: GradeChild ASSIGNMENT CLASSES_DIR GRADE_FILE");
      System.exit(2);
    }
    Assignment a = Assignments.byId(args[0]);
    Grade g;
    try {
      g = Grading.gradeClasses(a, Path.of(args[1]));
    } catch (RuntimeException | LinkageError e) {
      g =
          new Grade(
              a.id(),
              List.of(
                  Check.fail(
                      "grading ran", a.points(), "grading stopped: " + Solutions.describe(e))));
    }
    GradeFile.write(g, Path.of(args[2]));
    System.out.flush();
    // Student threads may still be running (a program stuck in a loop): end the JVM regardless.
    System.exit(0);
  }
}
