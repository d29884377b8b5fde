package org.jaria.classroom.grading;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.jaria.classroom.link.CompileReport;
import org.jaria.classroom.link.LinkLost;
import org.jaria.classroom.link.StudentStreams;
import org.jaria.classroom.sandbox.Cleanup;
import org.jaria.classroom.sandbox.SandboxUsers;
import org.jaria.classroom.sandbox.ScratchFiles;

/**
 * Runs one student's JVM and grades it over the robot link: starts it in the sandbox, where it
 * first compiles the student's sources and then runs them, stops it at the time limit (which covers
 * compiling and running) or when its scratch folder holds too many files or bytes, and names how it
 * ended.
 */
final class StudentRun {

  /** How often the files in a running student's scratch folder are counted, ms. */
  private static final long FILE_COUNT_EVERY_MS = 250;

  private final Assignment assignment;
  private final Grader.Options options;
  private final List<Path> studentClassPath;
  private final Set<Process> live;

  StudentRun(Assignment assignment, Grader.Options options, Set<Process> live) {
    this.assignment = assignment;
    this.options = options;
    this.live = live;
    this.studentClassPath = studentClassPath(assignment);
  }

  /**
   * Compiles and runs the student's sources in {@code scratch}/src in grading slot {@code slot},
   * their output going to {@code log}, and grades them; {@code t0} is when their grading began.
   */
  Grader.Result run(String student, Path scratch, Path log, int slot, long t0) throws IOException {
    try (SandboxUsers.Lease user = options.sandbox().user(slot)) {
      options.sandbox().prepare(scratch, user.uid());
      List<String> cmd =
          options
              .sandbox()
              .command(
                  scratch,
                  studentClassPath,
                  options.limits(),
                  user.uid(),
                  StudentMain.class.getName(),
                  List.of(assignment.id(), "/sandbox/src", "/sandbox/classes"));
      return run(student, scratch, log, cmd, t0);
    }
  }

  private Grader.Result run(String student, Path scratch, Path log, List<String> cmd, long t0)
      throws IOException {
    Process p = new ProcessBuilder(cmd).directory(scratch.toFile()).start();
    live.add(p);
    OutputCopier output =
        OutputCopier.start(
            p.getErrorStream(), log, options.limits().outputBytes(), "output-" + student);
    AtomicBoolean timedOut = new AtomicBoolean();
    AtomicBoolean tooManyFiles = new AtomicBoolean();
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
    // Nothing in the kernel limits how many files it makes or how much they hold together: count
    // them while it runs, so a flood is stopped early (the count after it ended decides).
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
    Run run = new Run(student, p, output, log, t0);
    try {
      StudentStreams streams = StudentStreams.of(p.getInputStream(), p.getOutputStream());
      CompileReport compiled;
      try {
        compiled = CompileReport.read(streams.in());
      } catch (IOException e) {
        run.end();
        return run.result(
            Outcomes.compileStatus(timedOut.get(), run.exit, run.tail(4000)),
            Outcomes.compileDetail(
                timedOut.get(), run.exit, options.timeout(), run.tail(400), options.texts()),
            "compiles.name");
      }
      if (compiled.outcome() != CompileReport.COMPILED) {
        run.end();
        Files.writeString(
            log, compiled.text() + "\n", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
        if (compiled.outcome() == CompileReport.ERRORS) {
          return new Grader.Result(
              student,
              Status.COMPILE_ERROR,
              Grading.compileFailure(assignment, compiled.text(), options.texts()),
              Grader.seconds(t0),
              log);
        }
        return run.result(
            Status.COMPILE_LIMIT,
            options.texts().get("compile.limit.failed", compiled.text()),
            "compiles.name");
      }
      return graded(run, streams, scratch, timedOut, tooManyFiles);
    } finally {
      alarm.cancel(false);
      fileCount.cancel(false);
      watchdog.shutdownNow();
      run.end();
      live.remove(p);
    }
  }

  private Grader.Result graded(
      Run run,
      StudentStreams streams,
      Path scratch,
      AtomicBoolean timedOut,
      AtomicBoolean tooManyFiles) {
    Grade grade = null;
    LinkLost lost = null;
    try {
      grade = assignment.grade(streams, options.texts());
    } catch (LinkLost e) {
      lost = e;
    } catch (RuntimeException e) {
      // Whatever the student's side did to the grader's half, it costs only this student.
      kill(run.process);
      run.end();
      return run.result(
          Status.CRASH, options.texts().get("ended.graderFailed", e.getMessage()), "ended.name");
    }
    run.end();
    if (tooManyFiles.get() || overFileLimit(scratch)) {
      return run.result(
          Status.TOO_MANY_FILES,
          Outcomes.detail(
              Status.TOO_MANY_FILES, run.exit, options.timeout(), run.tail(400), options.texts()),
          "ended.name");
    }
    if (grade != null && lost == null) {
      // A program that exhausted its threads or memory but caught the error still gets named so.
      Status exhausted = Outcomes.exhausted(run.tail(1 << 16));
      if (exhausted == null) {
        return new Grader.Result(
            run.student,
            Status.GRADED,
            Integrity.apply(grade, streams.audit(), options.texts()),
            Grader.seconds(run.t0),
            run.log);
      }
      lost = new LinkLost("resources exhausted", false, null);
    }
    Status status =
        Outcomes.classify(timedOut.get(), lost != null && lost.exiting(), run.exit, run.tail(4000));
    return run.result(
        status,
        Outcomes.detail(status, run.exit, options.timeout(), run.tail(400), options.texts()),
        "ended.name");
  }

  /** One student's JVM while it is graded, and how it ended. */
  private final class Run {
    final String student;
    final Process process;
    final OutputCopier output;
    final Path log;
    final long t0;
    int exit = -1;
    boolean ended;

    Run(String student, Process process, OutputCopier output, Path log, long t0) {
      this.student = student;
      this.process = process;
      this.output = output;
      this.log = log;
      this.t0 = t0;
    }

    /** Makes sure the JVM has ended, and its output is all in the log. */
    void end() {
      if (ended) {
        return;
      }
      ended = true;
      exit = waitOrKill(process);
      output.finish(TimeUnit.SECONDS.toMillis(5));
    }

    String tail(int max) {
      return StudentRun.tail(log, max);
    }

    /** A result with one failed check worth every point, named by catalogue key {@code nameKey}. */
    Grader.Result result(Status status, String message, String nameKey) {
      return new Grader.Result(
          student,
          status,
          new Grade(
              assignment.id(),
              List.of(Check.fail(options.texts().get(nameKey), assignment.points(), message))),
          Grader.seconds(t0),
          log);
    }
  }

  /** Whether the scratch folder holds more than the limits; an unreadable one is not counted. */
  private boolean overFileLimit(Path scratch) {
    try {
      return ScratchFiles.over(scratch, options.limits().files(), options.limits().scratchBytes());
    } catch (IOException e) {
      return false;
    }
  }

  private static void kill(Process p) {
    Cleanup.kill(p);
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
   * JAria's classes the student's JVM needs (and the assignment's own, for a pack), and nothing
   * else of this machine's.
   */
  static List<Path> studentClassPath(Assignment a) {
    Set<Path> parts = new LinkedHashSet<>();
    List<Class<?>> anchors =
        new ArrayList<>(
            List.of(
                Grader.class,
                org.jaria.robot.ArRobot.class,
                org.jaria.sim.SimWorld.class,
                org.jaria.arnl.ArPathPlanningTask.class,
                org.jaria.acts.ArACTS_1_2.class,
                org.slf4j.LoggerFactory.class));
    anchors.add(a.getClass());
    for (Class<?> anchor : anchors) {
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
