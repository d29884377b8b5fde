package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.jaria.classroom.sandbox.Cleanup;
import org.jaria.classroom.sandbox.Limits;
import org.jaria.classroom.sandbox.Sandbox;

/**
 * Grades a folder of submissions. Each student's Java files are copied into a scratch folder of
 * their own; their JVM, contained by the {@link Sandbox}, compiles them there and runs them, and is
 * graded from here over the robot link: the simulator, the ground truth, the checks and the grade
 * file all stay in this process, out of the student's reach.
 *
 * <p>This class runs the class: a pool of {@link Options#jobs()} grading slots, each student's
 * copy, and their files in the report. {@link StudentRun} runs and watches one student's JVM;
 * {@link SubmissionFolders} reads the submissions folder. Nothing here waits without a limit: each
 * student's grading is bounded by their time limit, and the class by the sum.
 */
public final class Grader {

  /** How the scratch folders in the scratch root are named. */
  public static final String SCRATCH_PREFIX = "jaria-grade-";

  /** What a student's grading may take beyond its time limit (ending, cleaning up), at most. */
  static final Duration GRACE = Duration.ofSeconds(60);

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
   * @param timeout real time allowed per student, compiling and running together
   * @param jobs how many students are graded at once
   * @param sandbox how student JVMs are contained
   * @param limits what each student JVM may use
   * @param texts the language of the checks
   * @param scratchRoot where the students' scratch folders are made (the system's temporary folder
   *     unless a test says otherwise)
   */
  public record Options(
      Duration timeout, int jobs, Sandbox sandbox, Limits limits, Texts texts, Path scratchRoot) {

    /** Options with the limits that go with {@code timeout}, the checks in English. */
    public static Options of(Duration timeout, int jobs, Sandbox sandbox) {
      return new Options(
          timeout,
          jobs,
          sandbox,
          Limits.forTimeout(timeout),
          Texts.english(),
          Path.of(System.getProperty("java.io.tmpdir")));
    }

    /** These options with the checks in {@code t}'s language. */
    public Options in(Texts t) {
      return new Options(timeout, jobs, sandbox, limits, t, scratchRoot);
    }

    /** These options making scratch folders in {@code root}. */
    public Options scratchIn(Path root) {
      return new Options(timeout, jobs, sandbox, limits, texts, root);
    }

    /** These options with other limits. */
    public Options limitedTo(Limits l) {
      return new Options(timeout, jobs, sandbox, l, texts, scratchRoot);
    }
  }

  private final Assignment assignment;
  private final Options options;
  private final Path workDir;

  /**
   * A grader for {@code assignment} that keeps each student's files (grade, feedback, output) under
   * {@code workDir}/FOLDER.
   */
  public Grader(Assignment assignment, Options options, Path workDir) {
    this.assignment = assignment;
    this.options = options;
    this.workDir = workDir;
  }

  /**
   * Grades {@code subs}, {@link Options#jobs()} at a time, each student's files going to their
   * folder in {@code folders}, calling {@code progress} as each ends (from the grading threads, one
   * call at a time); the results are in the order of {@code subs} whatever the order they finished
   * in. Stopping the grader (SIGTERM) removes its scratch folders.
   */
  public List<Result> gradeAll(
      List<SubmissionFolders.Submission> subs,
      Map<String, String> folders,
      Consumer<Result> progress)
      throws IOException {
    int jobs = Math.max(1, Math.min(options.jobs(), subs.size()));
    AtomicInteger n = new AtomicInteger();
    ExecutorService pool =
        Executors.newFixedThreadPool(jobs, r -> new Thread(r, "grade-" + n.incrementAndGet()));
    AtomicInteger slots = new AtomicInteger();
    ThreadLocal<Integer> slot = ThreadLocal.withInitial(slots::incrementAndGet);
    try (Cleanup cleanup = Cleanup.open()) {
      List<Future<Result>> futures = new ArrayList<>();
      for (SubmissionFolders.Submission s : subs) {
        futures.add(
            pool.submit(
                () -> {
                  Result r = gradeOne(s, folders.get(s.student()), slot.get(), cleanup);
                  synchronized (progress) {
                    progress.accept(r);
                  }
                  return r;
                }));
      }
      // Each student takes at most their time limit and the grace; the class at most its rounds.
      long perStudent = options.timeout().plus(GRACE).toNanos();
      long rounds = (subs.size() + jobs - 1L) / jobs;
      long deadline = System.nanoTime() + perStudent * rounds;
      List<Result> results = new ArrayList<>();
      for (int i = 0; i < futures.size(); i++) {
        Future<Result> f = futures.get(i);
        long left = Math.max(perStudent / 10, deadline - System.nanoTime());
        try {
          results.add(f.get(left, TimeUnit.NANOSECONDS));
        } catch (TimeoutException e) {
          f.cancel(true);
          results.add(unfinished(subs.get(i).student()));
        }
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

  private Result unfinished(String student) {
    return new Result(
        student,
        Status.CRASH,
        new Grade(
            assignment.id(),
            List.of(
                Check.fail(
                    options.texts().get("ended.name"),
                    assignment.points(),
                    options.texts().get("ended.unfinished")))),
        0,
        null);
  }

  /** Copies, compiles and grades the submission in {@code dir}, in grading slot {@code slot}. */
  public Result gradeOne(Path dir, int slot) throws IOException {
    String student = SubmissionFolders.studentOf(dir);
    try (Cleanup cleanup = Cleanup.open()) {
      return gradeOne(
          new SubmissionFolders.Submission(student, dir, false),
          SubmissionFolders.safeName(student),
          slot,
          cleanup);
    }
  }

  private Result gradeOne(SubmissionFolders.Submission s, String folder, int slot, Cleanup cleanup)
      throws IOException {
    String student = s.student();
    long t0 = System.nanoTime();
    Path work = workDir.resolve(folder);
    SubmissionFolders.deleteTree(work);
    Files.createDirectories(work);
    Path log = work.resolve("output.txt");
    Result r;
    if (s.link()) {
      r = notGraded(student, Status.NO_SUBMISSION, "nosub.name", "nosub.link", t0, log);
    } else {
      // A temporary folder of its own, not inside the report: the sandbox's command line, which
      // the student's process can read, then names no folder of the class.
      Files.createDirectories(options.scratchRoot());
      Path scratch =
          cleanup.track(Files.createTempDirectory(options.scratchRoot(), SCRATCH_PREFIX));
      try {
        // createDirectory, not createDirectories: if the grader is being stopped and its cleanup
        // has already deleted the scratch folder, this fails instead of making it again.
        Files.createDirectory(scratch.resolve("tmp"));
        Files.createDirectory(scratch.resolve("src"));
        SubmissionFolders.Copied copied =
            SubmissionFolders.copySources(s.dir(), scratch.resolve("src"));
        if (!copied.tooLarge().isEmpty()) {
          r =
              notGraded(
                  student,
                  Status.TOO_LARGE,
                  "compiles.name",
                  options.texts().get("large.failed", String.join("; ", copied.tooLarge())),
                  t0,
                  log);
        } else if (copied.files() == 0) {
          r = notGraded(student, Status.NO_SUBMISSION, "nosub.name", "nosub.empty", t0, log);
        } else {
          r =
              new StudentRun(assignment, options, cleanup.processes())
                  .run(student, scratch, log, slot, t0);
        }
        if (!copied.links().isEmpty()) {
          r =
              new Result(
                  r.student(),
                  r.status(),
                  r.grade()
                      .withNote(
                          options.texts().get("nosub.links", String.join(", ", copied.links()))),
                  r.seconds(),
                  r.log());
        }
      } finally {
        cleanup.delete(scratch);
      }
    }
    if (!Files.exists(log)) {
      Files.writeString(log, "", StandardCharsets.UTF_8);
    }
    ResultFiles.write(work, r);
    return r;
  }

  /** A result without a run: one failed check worth every point. */
  private Result notGraded(
      String student, Status status, String nameKey, String msg, long t0, Path log) {
    Texts t = options.texts();
    return new Result(
        student,
        status,
        new Grade(
            assignment.id(),
            List.of(
                Check.fail(t.get(nameKey), assignment.points(), t.has(msg) ? t.get(msg) : msg))),
        seconds(t0),
        log);
  }

  static double seconds(long t0) {
    return (System.nanoTime() - t0) / 1e9;
  }
}
