package org.jaria.classroom.pack;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
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
 * {@code jaria grade --new-pack DIR}'s template: it compiles as a pack, its solution earns full
 * marks and its starter less, and the JUnit test it carries passes as written.
 */
@Tag("slow")
class PackTemplateTest {

  @Test
  void theTemplateIsAPackWhoseOwnTestPasses(@TempDir Path tmp) throws Exception {
    Path pack = tmp.resolve("packs").resolve("parking");
    List<Path> files = PackTemplate.write(pack);
    assertTrue(
        files.contains(Path.of("test/parking/ParkingAssignmentTest.java")), files.toString());
    assertTrue(Files.isRegularFile(pack.resolve("src/" + Packs.SERVICES)));
    try (Packs packs = Packs.load(List.of(pack), tmp)) {
      Assignment a = packs.byId("parking");
      assertEquals(List.of("drives 1 m and stops"), a.checkNames(a.texts("en")));
      Grade solution = Grading.compileAndGrade(a, pack.resolve("solution"), tmp.resolve("s"));
      assertEquals(a.points(), solution.score(), solution.describe());
      Grade starter = Grading.compileAndGrade(a, pack.resolve("starter"), tmp.resolve("t"));
      assertTrue(starter.score() < a.points(), starter.describe());

      TestExecutionSummary s = PackJUnit.run(pack, packs, tmp);
      StringWriter w = new StringWriter();
      s.printFailuresTo(new PrintWriter(w), 20);
      assertEquals(0, s.getTotalFailureCount(), w.toString());
      assertEquals(3, s.getTestsSucceededCount(), w.toString());
    }
  }

  @Test
  void aPackNeedsANameThatIsAPackageAndANewFolder(@TempDir Path tmp) throws Exception {
    IllegalArgumentException bad =
        assertThrows(
            IllegalArgumentException.class, () -> PackTemplate.write(tmp.resolve("My-Pack")));
    assertTrue(bad.getMessage().contains("lowercase letters and digits"), bad.getMessage());
    Files.createDirectories(tmp.resolve("taken"));
    IllegalArgumentException exists =
        assertThrows(
            IllegalArgumentException.class, () -> PackTemplate.write(tmp.resolve("taken")));
    assertTrue(exists.getMessage().contains("already exists"), exists.getMessage());
  }

  @Test
  void whatIsNotAPackIsRefusedWithWhatAPackIs(@TempDir Path tmp) throws Exception {
    Files.createDirectories(tmp.resolve("empty"));
    IllegalArgumentException e =
        assertThrows(
            IllegalArgumentException.class, () -> Packs.load(List.of(tmp.resolve("empty")), tmp));
    assertTrue(e.getMessage().contains("a pack is a jar, or a folder with src/"), e.getMessage());
    Path broken = tmp.resolve("broken");
    PackTemplate.write(broken);
    Files.writeString(
        broken.resolve("src/broken/BrokenAssignment.java"), "package broken; class Nope {");
    IllegalArgumentException c =
        assertThrows(IllegalArgumentException.class, () -> Packs.load(List.of(broken), tmp));
    assertTrue(c.getMessage().contains("does not compile"), c.getMessage());
  }
}
