package dock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.jaria.classroom.grading.PoseTrace;
import org.jaria.classroom.grading.Texts;
import org.jaria.geom.ArPose;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The dock pack's own test: the solution parks for full marks, the starter does not, and the checks
 * measure what they say, as plain functions of a recorded path. Run it from the pack's folder (or
 * set -Djaria.pack=FOLDER), with JAria's jars and JUnit 5 on the class path.
 */
class DockAssignmentTest {

  private static final Path PACK = Path.of(System.getProperty("jaria.pack", "."));

  private final DockAssignment dock = new DockAssignment();

  @Test
  void theSolutionParksForFullMarks(@TempDir Path work) throws IOException {
    Grade g = Grading.compileAndGrade(dock, PACK.resolve("solution"), work);
    assertEquals(dock.points(), g.score(), g.describe());
  }

  @Test
  void theStarterDoesNot(@TempDir Path work) throws IOException {
    Grade g = Grading.compileAndGrade(dock, PACK.resolve("starter"), work);
    assertTrue(g.score() < dock.points(), g.describe());
    assertTrue(g.describe().contains("never came within 300 mm of the dock"), g.describe());
  }

  @Test
  void stoppingShortOfTheDockIsMeasuredFromTheTruePath() {
    ArPose at = DockAssignment.dock(DockAssignment.map());
    // the robot drove up to 120 mm short of the dock, facing it, and stopped
    PoseTrace trace =
        PoseTrace.recorded(
            new double[] {0, 10, 20},
            new double[] {at.x(), at.x(), at.x()},
            new double[] {at.y() - 2000, at.y() - 500, at.y() - 120},
            new double[] {90, 90, 90},
            new double[] {0, 300, 0});
    List<Check> checks = DockChecks.parking(trace, at, 0, 0, dock.texts("en"));
    assertTrue(checks.get(0).passed(), checks.get(0).message());
    assertFalse(checks.get(1).passed());
    assertTrue(checks.get(1).message().startsWith("stopped 120 mm from the dock"));
    assertTrue(checks.get(2).passed(), checks.get(2).message());
  }

  @Test
  void theChecksSpeakSpanishToo() {
    Texts es = dock.texts("es");
    assertEquals("llega al muelle", DockChecks.names(es).get(1));
    assertEquals("el programa termina", DockChecks.names(es).get(0));
  }
}
