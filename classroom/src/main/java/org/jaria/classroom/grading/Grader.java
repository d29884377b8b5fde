package org.jaria.classroom.grading;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import java.util.stream.Stream;
import org.jaria.classroom.link.LinkLost;
import org.jaria.classroom.link.StudentMain;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.classroom.sandbox.Limits;
import org.jaria.classroom.sandbox.Sandbox;
import org.jaria.classroom.sandbox.ScratchFiles;

/**
 * Grades a folder of submissions. Each student's Java files are copied into a scratch folder of
 * their own and compiled there by this JVM; then their program runs in a JVM of its own, contained
 * by the {@link Sandbox}, and is graded from here over the robot link: the simulator, the ground
 * truth, the checks and the grade file all stay in this process, out of the student's reach.
 *
 * <p>The submissions folder holds one folder per student (its name is the student's name) with
 * their {@code .java} files; a folder that holds {@code .java} files itself is one submission.
 * Originals are only read.
 */
public final class Grader {

  /** How often the files in a running student's scratch folder are counted, ms. */
  private static final long FILE_COUNT_EVERY_MS = 250;

  /** How the scratch folders in the system's temporary folder are named. */
  public static final String SCRATCH_PREFIX = "jaria-grade-";

  /** The most Java files, and bytes per file, copied from a submission. */
  static final int MAX_FILES = 200;

  static final long MAX_FILE_BYTES = 1 << 20;

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
  private final List<Path> studentClassPath = studentClassPath();

  /**
   * A grader for {@code assignment} that keeps each student's files (grade, feedback, output) under
   * {@code workDir}/NAME.
   */
  public Grader(Assignment assignment, Options options, Path workDir) {
    this.assignment = assignment;
    this.options = options;
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
          .filter(p -> Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS))
          .filter(p -> !p.getFileName().toString().startsWith("."))
          .toList();
    }
  }

  /** The student's name: the submission folder's name. */
  public static String studentOf(Path dir) {
    return dir.getFileName() == null ? dir.toString() : dir.getFileName().toString();
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
    String student = studentOf(dir);
    long t0 = System.nanoTime();
    Path work = workDir.resolve(safeName(student));
    deleteTree(work);
    Files.createDirectories(work);
    // A temporary folder of its own, not inside the report: the sandbox's command line, which the
    // student's process can read, then names no folder of the class.
    Path scratch = Files.createTempDirectory(SCRATCH_PREFIX);
    Files.createDirectories(scratch.resolve("tmp"));
    try {
      copySources(dir, scratch.resolve("src"));
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
        r = run(student, scratch, log, slot, t0);
      }
      ResultFiles.write(work, r);
      return r;
    } finally {
      deleteTree(scratch);
    }
  }

  private Result run(String student, Path scratch, Path log, int slot, long t0) throws IOException {
    options.sandbox().prepare(scratch, slot);
    List<String> cmd =
        options
            .sandbox()
            .command(
                scratch,
                studentClassPath,
                options.limits(),
                slot,
                StudentMain.class.getName(),
                List.of(assignment.id(), "/sandbox/classes"));
    Process p =
        new ProcessBuilder(cmd).directory(scratch.toFile()).redirectError(log.toFile()).start();
    AtomicBoolean timedOut = new AtomicBoolean();
    ScheduledExecutorService watchdog =
        Executors.newSingleThreadScheduledExecutor(r -> new Thread(r, "watchdog-" + student));
    ScheduledFuture<?> alarm =
        watchdog.schedule(
            () -> {
              timedOut.set(true);
              kill(p);
            },
            options.timeout().toMillis(),
            TimeUnit.MILLISECONDS);
    // Nothing in the kernel limits how many files it makes: count them while it runs, so a flood
    // of small files is stopped early (the count after it ended decides the status).
    AtomicBoolean tooManyFiles = new AtomicBoolean();
    ScheduledFuture<?> fileCount =
        watchdog.scheduleWithFixedDelay(
            () -> {
              if (overFileLimit(scratch)) {
                tooManyFiles.set(true);
                kill(p);
              }
            },
            FILE_COUNT_EVERY_MS,
            FILE_COUNT_EVERY_MS,
            TimeUnit.MILLISECONDS);
    Grade grade = null;
    LinkLost lost = null;
    try {
      grade =
          assignment.grade(
              StudentStreams.of(p.getInputStream(), p.getOutputStream()), options.texts());
    } catch (LinkLost e) {
      lost = e;
    } catch (RuntimeException e) {
      // Whatever the student's side did to the grader's half, it costs only this student.
      kill(p);
      waitOrKill(p);
      return new Result(
          student,
          Status.CRASH,
          new Grade(
              assignment.id(),
              List.of(
                  Check.fail(
                      options.texts().get("ended.name"),
                      assignment.points(),
                      options.texts().get("ended.graderFailed", e.getMessage())))),
          seconds(t0),
          log);
    } finally {
      alarm.cancel(false);
      fileCount.cancel(false);
      watchdog.shutdownNow();
    }
    int exit = waitOrKill(p);
    if (tooManyFiles.get() || overFileLimit(scratch)) {
      return new Result(
          student,
          Status.TOO_MANY_FILES,
          new Grade(
              assignment.id(),
              List.of(
                  Check.fail(
                      options.texts().get("ended.name"),
                      assignment.points(),
                      Outcomes.detail(
                          Status.TOO_MANY_FILES,
                          exit,
                          options.timeout(),
                          tail(log, 400),
                          options.texts())))),
          seconds(t0),
          log);
    }
    if (grade != null && lost == null) {
      // A program that exhausted its threads or memory but caught the error still gets named so.
      Status exhausted = Outcomes.exhausted(tail(log, 1 << 16));
      if (exhausted == null) {
        return new Result(student, Status.GRADED, grade, seconds(t0), log);
      }
      lost = new LinkLost("resources exhausted", false, null);
    }
    Status status =
        Outcomes.classify(timedOut.get(), lost != null && lost.exiting(), exit, tail(log, 4000));
    String detail =
        Outcomes.detail(status, exit, options.timeout(), tail(log, 400), options.texts());
    return new Result(
        student,
        status,
        new Grade(
            assignment.id(),
            List.of(Check.fail(options.texts().get("ended.name"), assignment.points(), detail))),
        seconds(t0),
        log);
  }

  /** Whether the scratch folder holds more than the limit; an unreadable one is not counted. */
  private boolean overFileLimit(Path scratch) {
    try {
      return ScratchFiles.over(scratch, options.limits().files());
    } catch (IOException e) {
      return false;
    }
  }

  private static void kill(Process p) {
    p.descendants().forEach(ProcessHandle::destroyForcibly);
    p.destroyForcibly();
  }

  /** Waits for the student's JVM to end (it is ending or killed), then its exit code. */
  private static int waitOrKill(Process p) {
    try {
      if (!p.waitFor(10, TimeUnit.SECONDS)) {
        kill(p);
        p.waitFor(10, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      kill(p);
      Thread.currentThread().interrupt();
    }
    return p.isAlive() ? -1 : p.exitValue();
  }

  /**
   * Copies the submission's .java files (regular files only: links are skipped, so a submission
   * cannot pull in another student's or the teacher's files) into {@code to}.
   */
  static void copySources(Path from, Path to) throws IOException {
    Files.createDirectories(to);
    int n = 0;
    try (Stream<Path> s = Files.walk(from, 8)) {
      for (Path p : s.sorted().toList()) {
        Path rel = from.relativize(p);
        if (!p.toString().endsWith(".java")
            || !Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)
            || hasLinkOrHidden(from, rel)
            || Files.size(p) > MAX_FILE_BYTES
            || ++n > MAX_FILES) {
          continue;
        }
        Path target = to.resolve(rel.toString());
        Files.createDirectories(target.getParent());
        Files.copy(p, target);
      }
    }
  }

  private static boolean hasLinkOrHidden(Path root, Path rel) {
    Path q = root;
    for (Path part : rel) {
      q = q.resolve(part);
      if (part.toString().startsWith(".") || Files.isSymbolicLink(q)) {
        return true;
      }
    }
    return false;
  }

  /** JAria's classes the student's JVM needs, and nothing else of this machine's. */
  static List<Path> studentClassPath() {
    Set<Path> parts = new LinkedHashSet<>();
    for (Class<?> anchor :
        List.of(
            Grader.class,
            org.jaria.robot.ArRobot.class,
            org.jaria.sim.SimWorld.class,
            org.jaria.arnl.ArPathPlanningTask.class,
            org.jaria.acts.ArACTS_1_2.class,
            org.slf4j.LoggerFactory.class)) {
      try {
        var src = anchor.getProtectionDomain().getCodeSource();
        if (src != null) {
          parts.add(Path.of(src.getLocation().toURI()).toRealPath());
        }
      } catch (URISyntaxException | IOException | SecurityException | IllegalArgumentException e) {
        throw new IllegalStateException(
            "cannot find where " + anchor.getName() + " is loaded from", e);
      }
    }
    try {
      // the student's program logs like the grader does, if the grader has a logger
      var simple = Class.forName("org.slf4j.simple.SimpleLogger").getProtectionDomain();
      if (simple.getCodeSource() != null) {
        parts.add(Path.of(simple.getCodeSource().getLocation().toURI()).toRealPath());
      }
    } catch (ClassNotFoundException | URISyntaxException | IOException e) {
      // no simple logger: SLF4J says once that it logs nothing
    }
    return List.copyOf(parts);
  }

  private static double seconds(long t0) {
    return (System.nanoTime() - t0) / 1e9;
  }

  static String safeName(String s) {
    return s.replaceAll("[^A-Za-z0-9._-]", "_");
  }

  /** The last {@code max} bytes of the student's output, decoded leniently. */
  static String tail(Path log, int max) {
    try (var ch = java.nio.channels.FileChannel.open(log)) {
      long size = ch.size();
      long from = Math.max(0, size - max);
      java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate((int) (size - from));
      while (b.hasRemaining() && ch.read(b, from + b.position()) > 0) {
        // read on
      }
      String s = new String(b.array(), 0, b.position(), StandardCharsets.UTF_8).strip();
      return s.isEmpty() ? "(none)" : s;
    } catch (IOException e) {
      return "(none)";
    }
  }

  static void deleteTree(Path p) throws IOException {
    if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
      return;
    }
    try (Stream<Path> s = Files.walk(p)) {
      for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
        Files.delete(q);
      }
    }
  }
}
