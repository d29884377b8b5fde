package org.jaria.classroom.attack;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.sandbox.Sandbox;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two gradings on one machine at once (two {@code jaria grade} runs, or two test JVMs) run their
 * students as different users when the grader is root. The kernel's process limit counts every
 * process of a user: had they one user, a thread or fork bomb in one class would leave an honest
 * student of the other unable to start, graded as a crash (this happened between two test JVMs).
 */
class ConcurrentGradingsTest {

  /** A student who waits long enough for the other grading's student to be running too. */
  private static final String WAITER =
      """
      import org.jaria.classroom.RobotProgram;
      import org.jaria.robot.ArRobot;
      public class Square implements RobotProgram {
        public void run(ArRobot robot) throws InterruptedException {
          Thread.sleep(6000);
        }
      }
      """;

  @TempDir Path tmp;

  @Test
  void theirStudentsNeverShareAUser() throws Exception {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    assumeTrue(
        Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid")),
        "students get users of their own only when the grader is root");
    CompletableFuture<String> a = grade("a");
    CompletableFuture<String> b = grade("b");
    // Both students' JVMs are running: each is a process of its sandbox user below the sandbox
    // whose command line names its grading's scratch root.
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
    Optional<Integer> uidA = Optional.empty();
    Optional<Integer> uidB = Optional.empty();
    while (System.nanoTime() < deadline && (uidA.isEmpty() || uidB.isEmpty())) {
      uidA = studentUid(tmp.resolve("a/scratch"));
      uidB = studentUid(tmp.resolve("b/scratch"));
      if (uidA.isEmpty() || uidB.isEmpty()) {
        TimeUnit.MILLISECONDS.sleep(20); // polling /proc: no event says a process started
      }
    }
    assertTrue(uidA.isPresent() && uidB.isPresent(), "both students ran at once: " + uidA + uidB);
    assertNotEquals(uidA.get(), uidB.get(), "the two gradings' students share a user");
    for (CompletableFuture<String> grading : List.of(a, b)) {
      String table = grading.get(120, TimeUnit.SECONDS);
      assertTrue(table.contains("GRADED"), table);
    }
  }

  private CompletableFuture<String> grade(String name) throws IOException {
    Path root = tmp.resolve(name);
    Path submission = root.resolve("submissions/student");
    Files.createDirectories(submission);
    Files.writeString(submission.resolve("Square.java"), WAITER, StandardCharsets.UTF_8);
    Files.createDirectories(root.resolve("scratch"));
    return CompletableFuture.supplyAsync(
        () -> {
          StringWriter out = new StringWriter();
          StringWriter err = new StringWriter();
          int exit;
          try {
            exit =
                ClassGrading.grade(
                    GradeRequest.of("square", root.resolve("submissions"), root.resolve("report"))
                        .withJobs(1)
                        .withTimeout(Duration.ofSeconds(20))
                        .withScratchRoot(root.resolve("scratch")),
                    new PrintWriter(out),
                    new PrintWriter(err));
          } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
          }
          assertEquals(0, exit, err.toString());
          return out.toString();
        });
  }

  /** The user of a running student JVM of the grading whose scratch root is {@code scratch}. */
  private static Optional<Integer> studentUid(Path scratch) {
    return ProcessHandle.allProcesses()
        .filter(p -> p.info().commandLine().map(c -> c.contains(scratch.toString())).orElse(false))
        .flatMap(ProcessHandle::descendants)
        .map(ConcurrentGradingsTest::uid)
        .flatMap(Optional::stream)
        .filter(u -> u >= Sandbox.BASE_UID)
        .findFirst();
  }

  private static Optional<Integer> uid(ProcessHandle p) {
    try {
      return Optional.of(
          (Integer) Files.getAttribute(Path.of("/proc", Long.toString(p.pid())), "unix:uid"));
    } catch (IOException | RuntimeException e) {
      return Optional.empty(); // ended meanwhile
    }
  }
}
