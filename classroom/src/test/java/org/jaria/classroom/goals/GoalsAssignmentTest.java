package org.jaria.classroom.goals;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.kit.Kit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Assignment 3 graded on the simulator. */
class GoalsAssignmentTest {

  private final GoalsAssignment goals = new GoalsAssignment();

  @Test
  void theReferenceSolutionEarnsFullMarks(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(goals, "solution", work);
    assertTrue(g.passed(), g.describe());
    assertEquals(goals.points(), g.maxScore());
  }

  @Test
  void theStarterAsksForEveryGoalAtOnceAndIsToldToWait(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(goals, "starter", work);
    assertFalse(g.passed(), g.describe());
    Check first =
        g.checks().stream()
            .filter(c -> c.name().startsWith("stopped at goal 1"))
            .findFirst()
            .orElseThrow();
    assertFalse(first.passed(), g.describe());
    assertTrue(first.message().contains("wait until path.isActive() is false"), first.message());
    // its program ends and the robot touches nothing, which earns nothing without the first goal
    assertEquals(0, g.score(), g.describe());
  }

  @Test
  void aProgramThatDoesNothingEarnsNothing(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            goals,
            "GoalTour.java",
            """
            import java.util.List;
            import org.jaria.arnl.ArPathPlanningTask;
            import org.jaria.classroom.NavigationProgram;
            import org.jaria.robot.ArRobot;
            public class GoalTour implements NavigationProgram {
              public void run(ArRobot robot, ArPathPlanningTask path, List<String> goals) {}
            }
            """,
            work);
    assertEquals(0, g.score(), g.describe());
    Check ends = g.checks().get(0);
    assertEquals("program ends", ends.name());
    assertTrue(ends.message().contains("earns nothing until the robot stops at"), ends.message());
  }
}
