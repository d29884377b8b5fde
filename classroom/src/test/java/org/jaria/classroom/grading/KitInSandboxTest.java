package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.jaria.classroom.sandbox.Sandbox;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The kit's reference solutions of the assignments with more than a robot across the process
 * boundary (sonar; localization and path planning; an ACTS channel beside the robot's) earn full
 * marks in the sandbox, and the ball's the very checks it earns in one JVM.
 */
class KitInSandboxTest {

  @Test
  void everySolutionEarnsFullMarksInTheSandbox(@TempDir Path tmp) throws IOException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    for (String id : List.of("wall", "goals", "ball")) {
      Assignment a = Assignments.byId(id);
      Path subs = tmp.resolve(id).resolve("subs");
      SubmissionFolders.copySources(
          Path.of("assignments", id, "solution"), subs.resolve("solution"));
      Grader grader =
          new Grader(
              a,
              Grader.Options.of(Duration.ofSeconds(60), 1, Sandbox.bubblewrap()),
              tmp.resolve(id).resolve("out"));
      Grader.Result r = grader.gradeOne(subs.resolve("solution"), 1);
      assertEquals(Status.GRADED, r.status(), id + ": " + r.grade().describe() + "\n" + output(r));
      assertEquals(a.points(), r.grade().score(), id + ": " + r.grade().describe());
      if (id.equals("ball")) {
        Grade inOneJvm =
            Grading.compileAndGrade(
                a, Path.of("assignments", id, "solution"), tmp.resolve("ball-classes"));
        assertEquals(inOneJvm.checks(), r.grade().checks());
      }
    }
  }

  private static String output(Grader.Result r) throws IOException {
    return r.log() != null && Files.exists(r.log()) ? Files.readString(r.log()) : "";
  }
}
