package org.jaria.classroom.square;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.ClassStats;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grader;
import org.jaria.classroom.grading.Status;
import org.jaria.classroom.kit.Kit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Assignment 1 graded on the simulator: the solution passes, the starter and typical bugs fail. */
class SquareAssignmentTest {

  private final SquareAssignment square = new SquareAssignment();

  @Test
  void theReferenceSolutionEarnsFullMarks(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(square, "solution", work);
    assertTrue(g.passed(), g.describe());
    assertEquals(square.points(), g.score(), g.describe());
    assertEquals(square.points(), g.maxScore());
  }

  @Test
  void theStarterFailsAtTheSecondCorner(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(square, "starter", work);
    assertFalse(g.passed(), g.describe());
    assertTrue(find(g, "corner 1 reached").passed(), g.describe());
    Check c2 = find(g, "corner 2 reached");
    assertFalse(c2.passed());
    assertTrue(c2.message().contains("corner 2 (2000, 2000)"), c2.message());
  }

  @Test
  void shortSidesAreReportedAsHowFarShortTheRobotStopped(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            square,
            "Square.java",
            """
            import org.jaria.classroom.RobotProgram;
            import org.jaria.robot.ArRobot;
            public class Square implements RobotProgram {
              public void run(ArRobot robot) throws InterruptedException {
                robot.enableMotors();
                for (int i = 0; i < 4; i++) {
                  robot.move(1400);
                  while (!robot.isMoveDone()) robot.getClock().sleepMillis(50);
                  robot.setDeltaHeading(90);
                  while (!robot.isHeadingDone()) robot.getClock().sleepMillis(50);
                }
              }
            }
            """,
            work);
    Check c1 = find(g, "corner 1 reached");
    assertFalse(c1.passed());
    assertTrue(c1.message().contains("it stopped 600 mm short of it"), c1.message());
  }

  @Test
  void turningRightIsCalledOut(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            square,
            "Square.java",
            """
            import org.jaria.classroom.RobotProgram;
            import org.jaria.robot.ArRobot;
            public class Square implements RobotProgram {
              public void run(ArRobot robot) throws InterruptedException {
                robot.enableMotors();
                for (int i = 0; i < 4; i++) {
                  robot.move(2000);
                  while (!robot.isMoveDone()) robot.getClock().sleepMillis(50);
                  robot.setDeltaHeading(-90);
                  while (!robot.isHeadingDone()) robot.getClock().sleepMillis(50);
                }
              }
            }
            """,
            work);
    assertTrue(find(g, "corner 1 reached").passed(), g.describe());
    Check c2 = find(g, "corner 2 reached");
    assertFalse(c2.passed());
    assertTrue(c2.message().contains("it turned right"), c2.message());
  }

  @Test
  void aProgramThatNeverWaitsOnTheClockIsToldHowToWait(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            square,
            "Square.java",
            """
            import org.jaria.classroom.RobotProgram;
            import org.jaria.robot.ArRobot;
            public class Square implements RobotProgram {
              public void run(ArRobot robot) {
                robot.enableMotors();
                robot.move(2000);
                while (!robot.isMoveDone()) {
                  if (Thread.currentThread().isInterrupted()) return;
                }
              }
            }
            """,
            work);
    Check ends = find(g, "program ends");
    assertFalse(ends.passed());
    assertTrue(ends.message().contains("robot.getClock().sleepMillis(50)"), ends.message());
    // one cause, one diagnosis: the corners and the stop are not judged, not "stopped short"
    // and "still moving" at once
    Check c1 = find(g, "corner 1 reached");
    assertTrue(c1.withheld(), g.describe());
    assertTrue(c1.message().contains("see 'program ends'"), c1.message());
    assertFalse(g.describe().contains("short of it"), g.describe());
    assertFalse(g.describe().contains("still moving"), g.describe());
    assertTrue(find(g, "stops at the end").withheld(), g.describe());
    assertEquals(
        Map.of("program ends", 1),
        ClassStats.of(List.of(new Grader.Result("x", Status.GRADED, g, 1, null)), square.points())
            .mostFailed());
  }

  @Test
  void aProgramThatNeverEndsIsNotToldItStoodStillAfterItEnded(@TempDir Path work)
      throws IOException {
    Grade g =
        Kit.gradeSource(
            square,
            "Square.java",
            """
            import org.jaria.classroom.RobotProgram;
            import org.jaria.robot.ArRobot;
            public class Square implements RobotProgram {
              public void run(ArRobot robot) throws InterruptedException {
                robot.enableMotors();
                robot.move(2000);
                while (true) robot.getClock().sleepMillis(50);
              }
            }
            """,
            work);
    assertTrue(find(g, "program ends").message().contains("still running after"), g.describe());
    assertTrue(find(g, "corner 1 reached").passed(), g.describe());
    Check stops = find(g, "stops at the end");
    assertTrue(stops.withheld(), g.describe());
    assertFalse(stops.message().contains("after your program ended"), stops.message());
  }

  static Check find(Grade g, String name) {
    return g.checks().stream()
        .filter(c -> c.name().equals(name))
        .findFirst()
        .orElseThrow(() -> new AssertionError("no check '" + name + "' in\n" + g.describe()));
  }
}
