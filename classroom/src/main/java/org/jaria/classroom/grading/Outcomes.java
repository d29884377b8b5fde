package org.jaria.classroom.grading;

import java.time.Duration;
import java.util.List;

/**
 * Naming how a student's JVM ended, from what the grader saw: whether its watchdog fired, whether
 * the JVM announced System.exit, its exit code and the end of its output. A plain function of those
 * values, so every case is tested as a value.
 */
final class Outcomes {

  /** Exit code of a JVM killed by SIGXCPU (its processor-time limit). */
  static final int CPU_LIMIT_EXIT = 128 + 24;

  /** Exit code of a JVM ended by -XX:+ExitOnOutOfMemoryError. */
  static final int OOM_EXIT = 3;

  private static final List<String> MEMORY =
      List.of(
          "OutOfMemoryError: Java heap space",
          "OutOfMemoryError: Metaspace",
          "OutOfMemoryError: Direct buffer memory",
          "OutOfMemoryError: Requested array size",
          "OutOfMemoryError: GC overhead");

  private static final List<String> TASKS =
      List.of(
          "unable to create native thread",
          "unable to create new native thread",
          "pthread_create failed",
          "Cannot fork",
          "error=11, Resource temporarily unavailable");

  private Outcomes() {}

  /** Whether the output shows the JVM ran out of memory or of threads/processes. */
  static Status exhausted(String log) {
    if (MEMORY.stream().anyMatch(log::contains)) {
      return Status.OUT_OF_MEMORY;
    }
    if (TASKS.stream().anyMatch(log::contains)) {
      return Status.TOO_MANY_THREADS;
    }
    return null;
  }

  /** The status of a JVM that ended before grading was done. */
  static Status classify(boolean timedOut, boolean announcedExit, int exitCode, String log) {
    if (timedOut || exitCode == CPU_LIMIT_EXIT) {
      return Status.TIMEOUT;
    }
    Status s = exhausted(log);
    if (s != null) {
      return s;
    }
    if (announcedExit) {
      return Status.EXIT;
    }
    // -XX:+ExitOnOutOfMemoryError ends the JVM with 3, its message on the link's stdout
    return exitCode == OOM_EXIT ? Status.OUT_OF_MEMORY : Status.CRASH;
  }

  /**
   * The status of a JVM that ended (or was stopped) while it compiled the submission: the compiler
   * ran out of time or memory (or of processor time), or the JVM crashed.
   */
  static Status compileStatus(boolean timedOut, int exitCode, String log) {
    boolean memory = exitCode == OOM_EXIT || log.contains("OutOfMemoryError");
    return timedOut || exitCode == CPU_LIMIT_EXIT || memory ? Status.COMPILE_LIMIT : Status.CRASH;
  }

  /** What the student reads about a compile that did not finish, in {@code t}'s language. */
  static String compileDetail(
      boolean timedOut, int exitCode, Duration timeout, String lastOutput, Texts t) {
    if (timedOut || exitCode == CPU_LIMIT_EXIT) {
      return t.get("compile.limit.time", timeout.toSeconds());
    }
    if (exitCode == OOM_EXIT || lastOutput.contains("OutOfMemoryError")) {
      return t.get("compile.limit.memory");
    }
    return t.get("outcome.crash", exitCode, lastOutput);
  }

  /** What the teacher and the student read about it, in {@code t}'s language. */
  static String detail(Status s, int exitCode, Duration timeout, String lastOutput, Texts t) {
    return switch (s) {
      case TIMEOUT -> t.get("outcome.timeout", timeout.toSeconds());
      case OUT_OF_MEMORY -> t.get("outcome.memory", lastOutput);
      case TOO_MANY_THREADS -> t.get("outcome.threads", lastOutput);
      case TOO_MANY_FILES -> t.get("outcome.files", lastOutput);
      case EXIT -> t.get("outcome.exit", exitCode);
      default -> t.get("outcome.crash", exitCode, lastOutput);
    };
  }
}
