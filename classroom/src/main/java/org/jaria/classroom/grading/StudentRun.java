package org.jaria.classroom.grading;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.jaria.classroom.link.LinkLost;
import org.jaria.classroom.link.StudentMain;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.classroom.sandbox.ScratchFiles;

/**
 * Runs one student's JVM and grades it over the robot link: starts it in the sandbox, stops it at
 * the time limit or when its scratch folder holds too many files, and names how it ended.
 */
final class StudentRun {

  /** How often the files in a running student's scratch folder are counted, ms. */
  private static final long FILE_COUNT_EVERY_MS = 250;

  private final Assignment assignment;
  private final Grader.Options options;
  private final List<Path> studentClassPath = studentClassPath();

  StudentRun(Assignment assignment, Grader.Options options) {
    this.assignment = assignment;
    this.options = options;
  }

  /**
   * Runs the student's compiled classes in {@code scratch} in grading slot {@code slot}, their
   * output going to {@code log}, and grades them; {@code t0} is when their grading began.
   */
  Grader.Result run(String student, Path scratch, Path log, int slot, long t0) throws IOException {
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
      return new Grader.Result(
          student,
          Status.CRASH,
          new Grade(
              assignment.id(),
              List.of(
                  Check.fail(
                      options.texts().get("ended.name"),
                      assignment.points(),
                      options.texts().get("ended.graderFailed", e.getMessage())))),
          Grader.seconds(t0),
          log);
    } finally {
      alarm.cancel(false);
      fileCount.cancel(false);
      watchdog.shutdownNow();
    }
    int exit = waitOrKill(p);
    if (tooManyFiles.get() || overFileLimit(scratch)) {
      return new Grader.Result(
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
          Grader.seconds(t0),
          log);
    }
    if (grade != null && lost == null) {
      // A program that exhausted its threads or memory but caught the error still gets named so.
      Status exhausted = Outcomes.exhausted(tail(log, 1 << 16));
      if (exhausted == null) {
        return new Grader.Result(student, Status.GRADED, grade, Grader.seconds(t0), log);
      }
      lost = new LinkLost("resources exhausted", false, null);
    }
    Status status =
        Outcomes.classify(timedOut.get(), lost != null && lost.exiting(), exit, tail(log, 4000));
    String detail =
        Outcomes.detail(status, exit, options.timeout(), tail(log, 400), options.texts());
    return new Grader.Result(
        student,
        status,
        new Grade(
            assignment.id(),
            List.of(Check.fail(options.texts().get("ended.name"), assignment.points(), detail))),
        Grader.seconds(t0),
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
}
