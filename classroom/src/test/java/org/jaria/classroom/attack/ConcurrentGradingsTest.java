package org.jaria.classroom.attack;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
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

  /**
   * A student who says, on their standard error (the report's output.txt), which user their JVM
   * runs as, and then that it is still running, with the time, every 50 ms for up to 6 s (until the
   * grader interrupts the program).
   */
  private static final String WAITER =
      """
      import java.nio.file.*;
      import org.jaria.classroom.RobotProgram;
      import org.jaria.robot.ArRobot;
      public class Square implements RobotProgram {
        public void run(ArRobot robot) throws InterruptedException {
          String uid = "?";
          try {
            for (String l : Files.readAllLines(Path.of("/proc/self/status"))) {
              if (l.startsWith("Uid:")) { uid = new java.util.Scanner(l.substring(4)).next(); }
            }
          } catch (java.io.IOException e) { uid = "unknown"; }
          long end = System.currentTimeMillis() + 6000;
          while (System.currentTimeMillis() < end) {
            System.err.println("alive " + uid + " " + System.currentTimeMillis());
            Thread.sleep(50);
          }
        }
      }
      """;

  /** What a student's output says: the user their JVM ran as, and when it first and last ran. */
  private record Alive(String uid, long first, long last) {}

  @TempDir Path tmp;

  @Test
  void theirStudentsNeverShareAUser() throws Exception {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    assumeTrue(
        Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid")),
        "students get users of their own only when the grader is root");
    CompletableFuture<String> a = grade("a");
    CompletableFuture<String> b = grade("b");
    for (CompletableFuture<String> grading : List.of(a, b)) {
      String table = grading.get(120, TimeUnit.SECONDS);
      assertTrue(table.contains("GRADED"), table);
    }
    // Read afterwards from the reports: the two JVMs ran at once when each said it was running
    // after the other had started and before the other had stopped.
    Alive inA = alive(tmp.resolve("a/report"));
    Alive inB = alive(tmp.resolve("b/report"));
    assertTrue(
        Math.max(inA.first(), inB.first()) <= Math.min(inA.last(), inB.last()),
        "both students ran at once: " + inA + " " + inB);
    assertNotEquals(inA.uid(), inB.uid(), "the two gradings' students share a user");
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

  /** The one student's output in the report folder {@code report}, read for its "alive" lines. */
  private static Alive alive(Path report) throws IOException {
    Path output;
    try (Stream<Path> files = Files.walk(report)) {
      output = files.filter(f -> f.getFileName().toString().equals("output.txt")).findFirst().get();
    }
    List<String[]> lines =
        Files.readAllLines(output, StandardCharsets.UTF_8).stream()
            .filter(l -> l.startsWith("alive "))
            .map(l -> l.split(" "))
            .toList();
    assertFalse(lines.isEmpty(), "the student said nothing: " + output);
    return new Alive(
        lines.get(0)[1],
        Long.parseLong(lines.get(0)[2]),
        Long.parseLong(lines.get(lines.size() - 1)[2]));
  }
}
