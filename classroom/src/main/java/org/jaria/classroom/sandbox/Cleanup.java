package org.jaria.classroom.sandbox;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Stream;

/**
 * What a grading run leaves on the machine while it runs (temporary folders, students' JVMs) and
 * must not leave behind when it is stopped: while {@link #open} the JVM's shutdown hook (run on
 * SIGTERM or Ctrl-C) kills the processes and deletes the folders, and {@link #close} does the same
 * at the normal end and takes the hook away again.
 */
public final class Cleanup implements AutoCloseable {

  private final Set<Path> folders = ConcurrentHashMap.newKeySet();
  private final Set<Process> processes = ConcurrentHashMap.newKeySet();
  private final Thread hook = new Thread(this::run, "grade-cleanup");

  private Cleanup() {}

  /** A cleanup whose shutdown hook is installed. */
  public static Cleanup open() {
    Cleanup c = new Cleanup();
    Runtime.getRuntime().addShutdownHook(c.hook);
    return c;
  }

  /** The processes to kill (students' JVMs while they run). */
  public Set<Process> processes() {
    return processes;
  }

  /** Deletes {@code folder} at the end, or when the grader is stopped. */
  public Path track(Path folder) {
    folders.add(folder);
    return folder;
  }

  /** Deletes {@code folder} now. */
  public void delete(Path folder) throws IOException {
    try {
      deleteTree(folder);
    } finally {
      folders.remove(folder);
    }
  }

  private void run() {
    // Grading threads run on while shutdown hooks do: one may start a student's JVM after the
    // first pass killed the others, or make a folder again after it was deleted. So passes repeat
    // until two in a row, 50 ms apart, find nothing left (or 5 s have passed).
    long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
    int quietPasses = 0;
    while (quietPasses < 2 && System.nanoTime() - end < 0) {
      boolean found = false;
      for (Process p : processes) {
        if (p.isAlive() || p.descendants().anyMatch(ProcessHandle::isAlive)) {
          kill(p);
          found = true;
        }
      }
      for (Path f : folders) {
        if (Files.exists(f, LinkOption.NOFOLLOW_LINKS)) {
          found = true;
          try {
            deleteTree(f);
          } catch (IOException | RuntimeException e) {
            // Still being written to: the next pass tries again.
          }
        }
      }
      quietPasses = found ? 0 : quietPasses + 1;
      if (quietPasses < 2) {
        LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(found ? 20 : 50));
      }
    }
  }

  /** Kills {@code p} and every process it started. */
  public static void kill(Process p) {
    p.descendants().forEach(ProcessHandle::destroyForcibly);
    p.destroyForcibly();
  }

  /** Deletes {@code p} and everything in it (links are deleted, not followed). */
  public static void deleteTree(Path p) throws IOException {
    if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
      return;
    }
    try (Stream<Path> s = Files.walk(p)) {
      for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(q);
      }
    }
  }

  @Override
  public void close() {
    try {
      Runtime.getRuntime().removeShutdownHook(hook);
    } catch (IllegalStateException e) {
      return; // the JVM is shutting down: the hook is running
    }
    run();
  }
}
