package org.jaria.classroom.pack;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.launcher.listeners.TestExecutionSummary;

/**
 * The example pack packs/dock ("park in the dock"), written only against the public API, loaded the
 * way {@code jaria grade --pack} loads it: its solution earns full marks, its starter less, and its
 * own JUnit test passes.
 */
@Tag("slow")
class DockPackTest {

  private static final Path DOCK = Path.of("packs", "dock");

  @Test
  void theDockIsGradedThroughThePackPath(@TempDir Path tmp) throws Exception {
    try (Packs packs = Packs.load(List.of(DOCK), tmp)) {
      Assignment dock = packs.byId("dock");
      assertEquals(
          List.of("square", "wall", "goals", "ball", "dock"),
          packs.assignments().stream().map(Assignment::id).toList());
      Grade solution = Grading.compileAndGrade(dock, DOCK.resolve("solution"), tmp.resolve("s"));
      assertEquals(dock.points(), solution.score(), solution.describe());
      Grade starter = Grading.compileAndGrade(dock, DOCK.resolve("starter"), tmp.resolve("t"));
      assertTrue(starter.score() < dock.points(), starter.describe());
      Grade spanish =
          Grading.compileAndGrade(
              dock, DOCK.resolve("starter"), tmp.resolve("e"), dock.texts("es"));
      assertTrue(spanish.describe().contains("llega al muelle"), spanish.describe());

      TestExecutionSummary s = PackJUnit.run(DOCK, packs, tmp);
      StringWriter w = new StringWriter();
      s.printFailuresTo(new PrintWriter(w), 20);
      assertEquals(0, s.getTotalFailureCount(), w.toString());
      assertEquals(4, s.getTestsSucceededCount(), w.toString());
    }
  }
}
