package org.jaria.classroom.grading;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.net.URLClassLoader;
import java.nio.file.Path;
import org.jaria.classroom.link.CompileReport;

/**
 * The main class of a student's JVM: it compiles the student's sources (inside the sandbox, under
 * the same limits as the run, annotation processing off, so no student code runs while compiling),
 * reports how that went as the link's first frame ({@link CompileReport}), then is the student's
 * side of the robot link over standard input and output. It knows only its assignment and the
 * student's own classes; the grade is made by the grader at the other end. Whatever the student's
 * code prints goes to standard error, so it cannot mix with the link (a program that writes to the
 * link's descriptor directly only breaks its own grading).
 */
public final class StudentMain {

  private StudentMain() {}

  /**
   * Ends this JVM when the student's code ran out of memory or threads: its output names the error,
   * which the grader reads to name the outcome.
   */
  private static void endOnResourceError(OutOfMemoryError e) {
    System.err.println("java.lang.OutOfMemoryError: " + e.getMessage());
    System.err.flush();
    Runtime.getRuntime().halt(3);
  }

  /** Arguments: assignment id, folder of the student's sources, folder for their classes. */
  public static void main(String[] args) throws IOException {
    DataOutputStream out =
        new DataOutputStream(
            new BufferedOutputStream(new FileOutputStream(FileDescriptor.out), 1 << 16));
    DataInputStream in =
        new DataInputStream(
            new BufferedInputStream(new FileInputStream(FileDescriptor.in), 1 << 16));
    System.setOut(System.err);
    System.setIn(new ByteArrayInputStream(new byte[0]));
    if (args.length != 3) {
      System.err.println(
          "usage: StudentMain ASSIGNMENT SOURCES_DIR CLASSES_DIR (started by the grader)");
      Runtime.getRuntime().halt(2);
    }
    Path classes = Path.of(args[2]);
    CompileReport compiled = compile(Path.of(args[1]), classes);
    compiled.write(out);
    if (compiled.outcome() != CompileReport.COMPILED) {
      System.err.flush();
      Runtime.getRuntime().halt(0);
    }
    Assignment a = Assignments.byId(args[0]);
    URLClassLoader loader = SolutionFinder.loaderFor(classes);
    StudentHarness harness =
        new StudentHarness(a, loader, SubmissionCompiler.classNames(classes), in, out);
    Runtime.getRuntime().addShutdownHook(new Thread(harness::announceExit, "announce-exit"));
    harness.onResourceError(StudentMain::endOnResourceError);
    Thread.setDefaultUncaughtExceptionHandler(
        (t, e) -> {
          if (e instanceof OutOfMemoryError oom) {
            endOnResourceError(oom);
          }
          System.err.println("Exception in thread \"" + t.getName() + "\" " + e);
        });
    try {
      harness.serve();
    } catch (IOException | RuntimeException | Error e) {
      // Not System.exit: end without the shutdown hook that would say so.
      System.err.println("student side: " + e);
      System.err.flush();
      Runtime.getRuntime().halt(1);
    }
    System.err.flush();
    // The student's threads may still run (a program that ignored its interrupt): end regardless,
    // and without their shutdown hooks.
    Runtime.getRuntime().halt(0);
  }

  /** Compiles the sources; whatever stops the compiler is reported, not thrown. */
  private static CompileReport compile(Path sources, Path classes) {
    try {
      SubmissionCompiler.Result r =
          SubmissionCompiler.compile(sources, classes, SubmissionCompiler.classPath());
      return r.ok()
          ? new CompileReport(CompileReport.COMPILED, "")
          : new CompileReport(CompileReport.ERRORS, r.errors());
    } catch (IOException | RuntimeException | StackOverflowError e) {
      return new CompileReport(CompileReport.COMPILER_FAILED, e.toString());
    }
  }
}
