package org.jaria.classroom.grading;

import java.io.IOException;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.List;

/**
 * Grading in this JVM: compile a folder of Java files, find the solution class, run the
 * assignment's checks. The {@link Grader} does the same for many students, each in a JVM of its
 * own; tests use this directly.
 */
public final class Grading {

  private Grading() {}

  /** Grades the solution among the classes compiled into {@code classesDir}. */
  public static Grade gradeClasses(Assignment a, Path classesDir) throws IOException {
    List<String> names = SubmissionCompiler.classNames(classesDir);
    try (URLClassLoader loader = SolutionFinder.loaderFor(classesDir)) {
      Class<?> solution;
      try {
        solution = SolutionFinder.find(a, loader, names);
      } catch (Solutions.SolutionException e) {
        return new Grade(a.id(), List.of(Check.fail("solution found", a.points(), e.getMessage())));
      }
      return a.grade(solution);
    }
  }

  /**
   * Compiles the Java files under {@code sourceDir} into {@code workDir} and grades them; a
   * submission that does not compile gets one failed check holding the compile errors.
   */
  public static Grade compileAndGrade(Assignment a, Path sourceDir, Path workDir)
      throws IOException {
    SubmissionCompiler.Result r =
        SubmissionCompiler.compile(sourceDir, workDir, SubmissionCompiler.classPath());
    if (!r.ok()) {
      return compileFailure(a, r.errors());
    }
    return gradeClasses(a, workDir);
  }

  /** The grade of a submission that does not compile. */
  static Grade compileFailure(Assignment a, String errors) {
    return new Grade(
        a.id(),
        List.of(
            Check.fail("compiles", a.points(), "your code does not compile:\n" + errors.strip())));
  }
}
