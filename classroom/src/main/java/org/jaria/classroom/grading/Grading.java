package org.jaria.classroom.grading;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URLClassLoader;
import java.nio.channels.Channels;
import java.nio.channels.Pipe;
import java.nio.file.Path;
import java.util.List;
import org.jaria.classroom.link.LinkAudit;
import org.jaria.classroom.link.StudentStreams;

/**
 * Grading in this JVM, for tests and for trying an assignment out: compile a folder of Java files
 * and grade it, with the student's side of the robot link on a thread of this JVM instead of a
 * process of its own. The grade is the same as {@link Grader} gives (the same link, the same
 * lockstep), but nothing is contained: use it only on code you trust, such as the kit's own.
 */
public final class Grading {

  private Grading() {}

  /** Grades the solution among the classes compiled into {@code classesDir}, in English. */
  public static Grade gradeClasses(Assignment a, Path classesDir) throws IOException {
    return gradeClasses(a, classesDir, a.texts("en"));
  }

  /** Grades the solution among the classes compiled into {@code classesDir}, in {@code t}. */
  public static Grade gradeClasses(Assignment a, Path classesDir, Texts t) throws IOException {
    return gradeClasses(a, classesDir, t, new LinkAudit());
  }

  /**
   * Grades the solution among the classes compiled into {@code classesDir}, in {@code t}, the robot
   * link keeping its record in {@code audit} (a test may pass one that lets more through, to try
   * the second line of defence on its own).
   */
  public static Grade gradeClasses(Assignment a, Path classesDir, Texts t, LinkAudit audit)
      throws IOException {
    List<String> names = SubmissionCompiler.classNames(classesDir);
    Pipe toStudent = Pipe.open();
    Pipe toGrader = Pipe.open();
    try (URLClassLoader loader =
        SolutionFinder.loaderFor(classesDir, a.getClass().getClassLoader())) {
      StudentHarness harness =
          new StudentHarness(
              a,
              loader,
              names,
              new DataInputStream(Channels.newInputStream(toStudent.source())),
              new DataOutputStream(Channels.newOutputStream(toGrader.sink())));
      Thread student =
          new Thread(
              () -> {
                try {
                  harness.serve();
                } catch (IOException e) {
                  // the grader's side ended first: it reports why
                } finally {
                  try {
                    toGrader.sink().close();
                  } catch (IOException e) {
                    // closing only wakes the grader's reads
                  }
                }
              },
              "student-side-" + a.id());
      student.setDaemon(true);
      student.start();
      try {
        StudentStreams streams =
            new StudentStreams(
                new DataInputStream(
                    new BufferedInputStream(Channels.newInputStream(toGrader.source()), 1 << 16)),
                new DataOutputStream(
                    new BufferedOutputStream(Channels.newOutputStream(toStudent.sink()), 1 << 16)),
                audit);
        return Integrity.apply(a.grade(streams, t), audit, t);
      } finally {
        toStudent.sink().close();
        try {
          student.join(10_000);
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
        }
      }
    } catch (UncheckedIOException e) {
      throw e.getCause();
    }
  }

  /**
   * Compiles the Java files under {@code sourceDir} into {@code workDir} and grades them; a
   * submission that does not compile gets one failed check holding the compile errors.
   */
  public static Grade compileAndGrade(Assignment a, Path sourceDir, Path workDir)
      throws IOException {
    return compileAndGrade(a, sourceDir, workDir, a.texts("en"));
  }

  /** {@link #compileAndGrade(Assignment, Path, Path)} with the checks in {@code t}'s language. */
  public static Grade compileAndGrade(Assignment a, Path sourceDir, Path workDir, Texts t)
      throws IOException {
    SubmissionCompiler.Result r =
        SubmissionCompiler.compile(sourceDir, workDir, SubmissionCompiler.classPath(a));
    if (!r.ok()) {
      return compileFailure(a, r.errors(), t);
    }
    return gradeClasses(a, workDir, t);
  }

  /** The grade of a submission that does not compile. */
  static Grade compileFailure(Assignment a, String errors, Texts t) {
    return new Grade(
        a.id(),
        List.of(
            Check.fail(
                t.get("compiles.name"), a.points(), t.get("compiles.failed", errors.strip()))));
  }

  /**
   * The grade of a solution that could not be set up, from the student's side's answer ({@link
   * Solutions#setUpAnswer}), in {@code t}'s language. An answer that names no sentence of the
   * catalogue is shown as it is.
   */
  public static Grade setUpFailure(Assignment a, String answer, Texts t) {
    int tab = answer.indexOf('\t');
    String nameKey = tab < 0 ? "setup.created.name" : answer.substring(0, tab);
    List<String> msg = Solutions.fields(tab < 0 ? "" : answer.substring(tab + 1));
    if (tab < 0 || !t.has(nameKey) || !t.has(msg.get(0))) {
      return new Grade(
          a.id(), List.of(Check.fail(t.get("setup.created.name"), a.points(), answer)));
    }
    Object[] args = msg.subList(1, msg.size()).toArray();
    return new Grade(
        a.id(), List.of(Check.fail(t.get(nameKey), a.points(), t.get(msg.get(0), args))));
  }
}
