package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * Grades a folder of submissions: each student's Java files are compiled in this JVM, then graded
 * in a JVM of their own with a time limit, so a submission that does not compile, throws, loops
 * forever or calls {@code System.exit} costs only its own grade.
 *
 * <p>The submissions folder holds one folder per student (its name is the student's name) with
 * their {@code .java} files; a folder that holds {@code .java} files itself is one submission.
 */
public final class Grader {

  /** What happened to one submission. */
  public enum Status {
    /** Compiled and graded (the grade says how well it did). */
    GRADED,
    /** No Java files, or they do not compile. */
    COMPILE_ERROR,
    /** Still running at the time limit; its JVM was killed. */
    TIMED_OUT,
    /** Its JVM ended without a grade (System.exit, out of memory, ...). */
    CRASHED
  }

  /**
   * One student's result.
   *
   * @param student the student (the folder's name)
   * @param status what happened
   * @param grade the checks (for every status: failures are checks too)
   * @param seconds real time taken
   * @param log where the submission's own output went, or null
   */
  public record Result(String student, Status status, Grade grade, double seconds, Path log) {}

  private final Assignment assignment;
  private final Duration timeout;
  private final Path workDir;
  private final String classPath = SubmissionCompiler.classPath();

  /**
   * A grader for {@code assignment} that gives each submission {@code timeout} of real time and
   * keeps its compiled classes and output under {@code workDir}.
   */
  public Grader(Assignment assignment, Duration timeout, Path workDir) {
    this.assignment = assignment;
    this.timeout = timeout;
    this.workDir = workDir;
  }

  /**
   * The submissions in {@code folder}: its sub-folders, by name, or the folder itself if it holds
   * Java files directly.
   *
   * @throws IOException if the folder cannot be read
   */
  public static List<Path> submissions(Path folder) throws IOException {
    if (!Files.isDirectory(folder)) {
      throw new IOException("not a folder: " + folder);
    }
    try (Stream<Path> s = Files.list(folder)) {
      List<Path> entries = s.sorted().toList();
      if (entries.stream()
          .anyMatch(p -> p.toString().endsWith(".java") && Files.isRegularFile(p))) {
        return List.of(folder);
      }
      return entries.stream()
          .filter(Files::isDirectory)
          .filter(p -> !p.getFileName().toString().startsWith("."))
          .toList();
    }
  }

  /** Grades every submission in {@code folder}, in name order. */
  public List<Result> gradeAll(Path folder, java.util.function.Consumer<Result> progress)
      throws IOException {
    List<Result> results = new ArrayList<>();
    for (Path dir : submissions(folder)) {
      Result r = gradeOne(dir);
      progress.accept(r);
      results.add(r);
    }
    return results;
  }

  /** Compiles and grades one submission. */
  public Result gradeOne(Path dir) throws IOException {
    String student = dir.getFileName() == null ? dir.toString() : dir.getFileName().toString();
    long t0 = System.nanoTime();
    Path work = workDir.resolve(safeName(student));
    Path classes = work.resolve("classes");
    deleteTree(work);
    Files.createDirectories(work);
    SubmissionCompiler.Result compiled = SubmissionCompiler.compile(dir, classes, classPath);
    if (!compiled.ok()) {
      Path log = work.resolve("compile-errors.txt");
      Files.writeString(log, compiled.errors() + "\n", StandardCharsets.UTF_8);
      return new Result(
          student,
          Status.COMPILE_ERROR,
          Grading.compileFailure(assignment, compiled.errors()),
          seconds(t0),
          log);
    }
    Path gradeFile = work.resolve("grade.txt");
    Path log = work.resolve("output.txt");
    Process p =
        new ProcessBuilder(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx768m",
                "-Djava.awt.headless=true",
                "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn",
                "-cp",
                classPath,
                GradeChild.class.getName(),
                assignment.id(),
                classes.toString(),
                gradeFile.toString())
            .redirectErrorStream(true)
            .redirectOutput(log.toFile())
            .start();
    boolean done;
    try {
      done = p.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS);
    } catch (InterruptedException e) {
      p.destroyForcibly();
      Thread.currentThread().interrupt();
      throw new IOException("interrupted while grading " + student, e);
    }
    if (!done) {
      p.destroyForcibly();
      try {
        p.waitFor(10, TimeUnit.SECONDS);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
      return new Result(
          student,
          Status.TIMED_OUT,
          single(
              "finishes in time",
              "grading was still running after "
                  + timeout.toSeconds()
                  + " s of real time and was stopped: look for a loop that never ends in a"
                  + " constructor or in fire() (they run on the robot's cycle, which then never"
                  + " finishes)"),
          seconds(t0),
          log);
    }
    if (!Files.isRegularFile(gradeFile)) {
      return new Result(
          student,
          Status.CRASHED,
          single(
              "grading ran",
              "grading ended (exit code "
                  + p.exitValue()
                  + ") without a grade: did your code call System.exit? Last output: "
                  + tail(log)),
          seconds(t0),
          log);
    }
    return new Result(student, Status.GRADED, GradeFile.read(gradeFile), seconds(t0), log);
  }

  private Grade single(String name, String message) {
    return new Grade(assignment.id(), List.of(Check.fail(name, assignment.points(), message)));
  }

  private static double seconds(long t0) {
    return (System.nanoTime() - t0) / 1e9;
  }

  private static String safeName(String s) {
    return s.replaceAll("[^A-Za-z0-9._-]", "_");
  }

  private static String tail(Path log) {
    try {
      String s = Files.readString(log, StandardCharsets.UTF_8).strip();
      return s.isEmpty() ? "(none)" : s.substring(Math.max(0, s.length() - 400));
    } catch (IOException e) {
      return "(none)";
    }
  }

  private static void deleteTree(Path p) throws IOException {
    if (!Files.exists(p)) {
      return;
    }
    try (Stream<Path> s = Files.walk(p)) {
      for (Path q : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
        Files.delete(q);
      }
    }
  }
}
