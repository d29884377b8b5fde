package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.sandbox.Sandbox;
import org.jaria.classroom.square.SquareAssignment;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A grader stopped with SIGTERM (a teacher's Ctrl-C, a CI job cancelled) leaves nothing behind: its
 * scratch folders are deleted and the students' JVMs are gone.
 */
@Tag("slow")
class StopTest {

  /** Grades {@code args[0]} into {@code args[1]} with scratch folders in {@code args[2]}. */
  public static void main(String[] args) throws IOException {
    PrintWriter o = new PrintWriter(System.out, true, StandardCharsets.UTF_8);
    ClassGrading.grade(
        GradeRequest.of("square", Path.of(args[0]), Path.of(args[1]))
            .withTimeout(Duration.ofMinutes(5))
            .withScratchRoot(Path.of(args[2])),
        o,
        o);
  }

  @Test
  void aStoppedGraderRemovesItsScratchFolders(@TempDir Path tmp)
      throws IOException, InterruptedException, URISyntaxException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    Path subs = tmp.resolve("subs");
    Files.createDirectories(subs.resolve("waiter"));
    // waits on the robot's clock forever: its grading lasts until the grader is stopped
    Files.writeString(
        subs.resolve("waiter/Square.java"),
        "import org.jaria.classroom.RobotProgram;\nimport org.jaria.robot.ArRobot;\n"
            + "public class Square implements RobotProgram {\n  public void run(ArRobot robot)"
            + " throws InterruptedException {\n    while (true) { robot.getClock().sleepMillis(50);"
            + " }\n  }\n}\n");
    Path scratch = tmp.resolve("scratch");
    Files.createDirectories(scratch);
    List<String> cp = new ArrayList<>();
    for (Path p : StudentRun.studentClassPath(new SquareAssignment())) {
      cp.add(p.toString());
    }
    cp.add(
        Path.of(StopTest.class.getProtectionDomain().getCodeSource().getLocation().toURI())
            .toString());
    Process grader =
        new ProcessBuilder(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp",
                String.join(java.io.File.pathSeparator, cp),
                StopTest.class.getName(),
                subs.toString(),
                tmp.resolve("out").toString(),
                scratch.toString())
            .redirectErrorStream(true)
            .redirectOutput(tmp.resolve("grader.txt").toFile())
            .start();
    try (WatchService watch = FileSystems.getDefault().newWatchService()) {
      scratch.register(watch, StandardWatchEventKinds.ENTRY_CREATE);
      WatchKey created = watch.poll(120, TimeUnit.SECONDS);
      assertTrue(created != null, "the grader made no scratch folder");
      assertTrue(names(scratch).stream().anyMatch(n -> n.startsWith(Grader.SCRATCH_PREFIX)));
      grader.destroy(); // SIGTERM
      assertTrue(grader.waitFor(60, TimeUnit.SECONDS), "the grader did not stop");
      String said = Files.readString(tmp.resolve("grader.txt"));
      assertEquals(List.of(), names(scratch), said);
      List<String> left =
          ProcessHandle.allProcesses()
              .filter(
                  p ->
                      p.info().commandLine().map(c -> c.contains(scratch.toString())).orElse(false))
              .map(p -> p.pid() + " " + p.info().commandLine().orElse(""))
              .toList();
      assertEquals(List.of(), left);
    } finally {
      grader.destroyForcibly();
    }
  }

  private static List<String> names(Path dir) throws IOException {
    try (Stream<Path> s = Files.list(dir)) {
      return s.map(p -> p.getFileName().toString()).toList();
    }
  }
}
