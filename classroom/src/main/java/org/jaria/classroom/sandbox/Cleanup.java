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
    for (Process p : processes) {
      kill(p);
    }
    for (Path f : folders) {
      // A grading thread may still be writing in it (threads run on while shutdown hooks do), and
      // on a busy machine it can keep doing so for a while: try again, for up to 5 s.
      long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
      while (true) {
        try {
          deleteTree(f);
          break;
        } catch (IOException | RuntimeException e) {
          if (System.nanoTime() - end > 0) {
            break;
          }
          LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
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
