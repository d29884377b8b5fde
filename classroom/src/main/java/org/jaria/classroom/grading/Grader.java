package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.jaria.classroom.sandbox.Limits;
import org.jaria.classroom.sandbox.Sandbox;

/**
 * Grades a folder of submissions. Each student's Java files are copied into a scratch folder of
 * their own and compiled there by this JVM; then their program runs in a JVM of its own, contained
 * by the {@link Sandbox}, and is graded from here over the robot link: the simulator, the ground
 * truth, the checks and the grade file all stay in this process, out of the student's reach.
 *
 * <p>This class runs the class: a pool of {@link Options#jobs()} grading slots, each student's copy
 * and compile, and their files in the report. {@link StudentRun} runs and watches one student's
 * JVM; {@link SubmissionFolders} reads the submissions folder.
 */
public final class Grader {

  /** How the scratch folders in the system's temporary folder are named. */
  public static final String SCRATCH_PREFIX = "jaria-grade-";

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

  /**
   * How to grade.
   *
   * @param timeout real time allowed per student
   * @param jobs how many students are graded at once
   * @param sandbox how student JVMs are contained
   * @param limits what each student JVM may use
   * @param texts the language of the checks
   */
  public record Options(Duration timeout, int jobs, Sandbox sandbox, Limits limits, Texts texts) {

    /** Options with the limits that go with {@code timeout}, the checks in English. */
    public static Options of(Duration timeout, int jobs, Sandbox sandbox) {
      return new Options(timeout, jobs, sandbox, Limits.forTimeout(timeout), Texts.english());
    }

    /** These options with the checks in {@code t}'s language. */
    public Options in(Texts t) {
      return new Options(timeout, jobs, sandbox, limits, t);
    }
  }

  private final Assignment assignment;
  private final Options options;
  private final Path workDir;
  private final String compileClassPath = SubmissionCompiler.classPath();
  private final StudentRun studentRun;

  /**
   * A grader for {@code assignment} that keeps each student's files (grade, feedback, output) under
   * {@code workDir}/NAME.
   */
  public Grader(Assignment assignment, Options options, Path workDir) {
    this.assignment = assignment;
    this.options = options;
    this.workDir = workDir;
    this.studentRun = new StudentRun(assignment, options);
  }

  /**
   * Grades {@code dirs}, {@link Options#jobs()} at a time, calling {@code progress} as each ends
   * (from the grading threads, one call at a time); the results are in the order of {@code dirs}
   * whatever the order they finished in.
   */
  public List<Result> gradeAll(List<Path> dirs, Consumer<Result> progress) throws IOException {
    int jobs = Math.max(1, Math.min(options.jobs(), dirs.size()));
    BlockingQueue<Integer> slots = new ArrayBlockingQueue<>(jobs);
    for (int i = 0; i < jobs; i++) {
      slots.add(i + 1);
    }
    AtomicInteger n = new AtomicInteger();
    ExecutorService pool =
        Executors.newFixedThreadPool(jobs, r -> new Thread(r, "grade-" + n.incrementAndGet()));
    try {
      List<Future<Result>> futures = new ArrayList<>();
      for (Path dir : dirs) {
        futures.add(
            pool.submit(
                () -> {
                  int slot = slots.take();
                  try {
                    Result r = gradeOne(dir, slot);
                    synchronized (progress) {
                      progress.accept(r);
                    }
                    return r;
                  } finally {
                    slots.add(slot);
                  }
                }));
      }
      List<Result> results = new ArrayList<>();
      for (Future<Result> f : futures) {
        results.add(f.get());
      }
      return results;
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new IOException("interrupted while grading", e);
    } catch (ExecutionException e) {
      Throwable c = e.getCause();
      if (c instanceof IOException io) {
        throw io;
      }
      throw new IOException("grading failed: " + c, c);
    } finally {
      pool.shutdownNow();
    }
  }

  /** Copies, compiles and grades one submission, in grading slot {@code slot}. */
  public Result gradeOne(Path dir, int slot) throws IOException {
    String student = SubmissionFolders.studentOf(dir);
    long t0 = System.nanoTime();
    Path work = workDir.resolve(SubmissionFolders.safeName(student));
    SubmissionFolders.deleteTree(work);
    Files.createDirectories(work);
    // A temporary folder of its own, not inside the report: the sandbox's command line, which the
    // student's process can read, then names no folder of the class.
    Path scratch = Files.createTempDirectory(SCRATCH_PREFIX);
    Files.createDirectories(scratch.resolve("tmp"));
    try {
      SubmissionFolders.copySources(dir, scratch.resolve("src"));
      SubmissionCompiler.Result compiled =
          SubmissionCompiler.compile(
              scratch.resolve("src"), scratch.resolve("classes"), compileClassPath);
      Path log = work.resolve("output.txt");
      Result r;
      if (!compiled.ok()) {
        Files.writeString(log, compiled.errors() + "\n", StandardCharsets.UTF_8);
        r =
            new Result(
                student,
                Status.COMPILE_ERROR,
                Grading.compileFailure(assignment, compiled.errors(), options.texts()),
                seconds(t0),
                log);
      } else {
        r = studentRun.run(student, scratch, log, slot, t0);
      }
      ResultFiles.write(work, r);
      return r;
    } finally {
      SubmissionFolders.deleteTree(scratch);
    }
  }

  static double seconds(long t0) {
    return (System.nanoTime() - t0) / 1e9;
  }
}
