package org.jaria.classroom.ball;

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

/** Assignment 4 graded on the simulator (camera, ACTS, ArACTS_1_2, all in lockstep). */
class BallAssignmentTest {

  private final BallAssignment ball = new BallAssignment();

  @Test
  void theReferenceSolutionEarnsFullMarks(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(ball, "solution", work);
    assertTrue(g.passed(), g.describe());
    assertEquals(ball.points(), g.maxScore());
  }

  @Test
  void theStarterNeverMovesAndIsToldWhatToSet(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(ball, "starter", work);
    assertFalse(g.passed(), g.describe());
    Check approach =
        g.checks().stream()
            .filter(c -> c.name().equals("drives up to the ball"))
            .findFirst()
            .orElseThrow();
    assertFalse(approach.passed());
    assertTrue(approach.message().contains("desired.setVel(200)"), approach.message());
    // a robot that never moves "stops when the ball is gone" and touches nothing: worth nothing
    assertEquals(0, g.score(), g.describe());
  }

  @Test
  void anActionThatDoesNothingEarnsNothing(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            ball,
            "BallFollower.java",
            """
            import org.jaria.action.ArAction;
            import org.jaria.action.ArActionDesired;
            import org.jaria.acts.ArACTS_1_2;
            public class BallFollower extends ArAction {
              public BallFollower(ArACTS_1_2 acts) { super("ball"); }
              public ArActionDesired fire(ArActionDesired current) {
                return new ArActionDesired();
              }
            }
            """,
            work);
    assertEquals(0, g.score(), g.describe());
    assertEquals(ball.points(), g.maxScore(), g.describe());
  }

  @Test
  void aSolutionWithoutTheActsConstructorIsToldWhichConstructorItNeeds(@TempDir Path work)
      throws IOException {
    Grade g =
        Kit.gradeSource(
            ball,
            "BallFollower.java",
            """
            import org.jaria.action.ArAction;
            import org.jaria.action.ArActionDesired;
            public class BallFollower extends ArAction {
              public BallFollower() { super("ball"); }
              public ArActionDesired fire(ArActionDesired current) { return null; }
            }
            """,
            work);
    assertEquals(0, g.score());
    assertTrue(g.checks().get(0).message().contains("BallFollower(ArACTS_1_2)"), g.describe());
  }
}
