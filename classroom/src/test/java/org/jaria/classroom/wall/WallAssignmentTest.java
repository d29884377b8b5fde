package org.jaria.classroom.wall;

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

/** Assignment 2 graded on the simulator. */
class WallAssignmentTest {

  private final WallAssignment wall = new WallAssignment();

  @Test
  void theReferenceSolutionEarnsFullMarks(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(wall, "solution", work);
    assertTrue(g.passed(), g.describe());
    assertEquals(wall.points(), g.maxScore());
  }

  @Test
  void theStarterDrivesStraightIntoTheCorner(@TempDir Path work) throws IOException {
    Grade g = Kit.grade(wall, "starter", work);
    assertFalse(g.passed(), g.describe());
    Check corner = find(g, "turns the corner");
    assertFalse(corner.passed());
    assertTrue(corner.message().contains("turn left"), corner.message());
    assertFalse(find(g, "no collisions").passed(), g.describe());
    // it drives straight along the first wall, keeping its distance without steering: that earns
    // nothing until the robot turns the corner
    assertEquals(0, g.score(), g.describe());
    Check kept = g.checks().stream().filter(c -> c.name().startsWith("keeps")).findFirst().get();
    assertTrue(
        kept.message().contains("earns nothing until the robot turns the corner"), kept.message());
  }

  @Test
  void anActionThatDoesNothingEarnsNothing(@TempDir Path work) throws IOException {
    Grade g =
        Kit.gradeSource(
            wall,
            "WallFollower.java",
            """
            import org.jaria.action.ArAction;
            import org.jaria.action.ArActionDesired;
            public class WallFollower extends ArAction {
              public WallFollower() { super("wall follower"); }
              public ArActionDesired fire(ArActionDesired current) { return null; }
            }
            """,
            work);
    assertEquals(0, g.score(), g.describe());
    assertEquals(wall.points(), g.maxScore(), g.describe());
  }

  @Test
  void anActionThatThrowsIsReportedWithTheLineOfTheStudentsCode(@TempDir Path work)
      throws IOException {
    Grade g =
        Kit.gradeSource(
            wall,
            "WallFollower.java",
            """
            import org.jaria.action.ArAction;
            import org.jaria.action.ArActionDesired;
            public class WallFollower extends ArAction {
              private ArActionDesired desired;
              public WallFollower() { super("wall follower"); }
              public ArActionDesired fire(ArActionDesired current) {
                desired.setVel(300);
                return desired;
              }
            }
            """,
            work);
    Check c = find(g, "fire() runs without errors");
    assertFalse(c.passed());
    assertTrue(c.message().contains("NullPointerException"), c.message());
    assertTrue(c.message().contains("WallFollower.java:7"), c.message());
    Check along = find(g, "drives along the wall");
    assertTrue(along.message().contains("hardly moved"), along.message());
    assertEquals(0, g.score(), g.describe());
  }

  @Test
  void progressFollowsTheCourse() {
    assertEquals(0, WallAssignment.progress(0, 600), 1e-9);
    assertEquals(5000, WallAssignment.progress(5000, 700), 1e-9);
    assertEquals(7400 + 2000, WallAssignment.progress(7350, 2600), 1e-9);
    assertEquals(600, WallAssignment.wallDistance(3000, 600), 1e-9);
    assertEquals(500, WallAssignment.wallDistance(7500, 3000), 1e-9);
  }

  static Check find(Grade g, String name) {
    return g.checks().stream()
        .filter(c -> c.name().equals(name))
        .findFirst()
        .orElseThrow(() -> new AssertionError("no check '" + name + "' in\n" + g.describe()));
  }
}
