package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.jaria.classroom.link.LinkAudit;
import org.jaria.classroom.pack.Packs;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * No grade without driving, for every assignment there is (the kit's and the example pack's): a
 * program that never drives but moves the simulated robot onto the assignment's targets with
 * MobileSim's SIM_SET_POSE through its own robot link gets nothing. The link carries no simulator
 * command to the world (and the grade's notes say what it dropped); and if one got through anyway,
 * the jump of the robot's true path would cost the whole grade. Each assignment needs its attack in
 * src/test/resources/attacks/ID/.
 */
@Tag("slow")
class TeleportAttackTest {

  static Path packsWork;
  static Packs packs;

  @BeforeAll
  static void loadPacks() throws IOException {
    packsWork = Files.createTempDirectory("teleport-packs");
    packs = Packs.load(List.of(Path.of("packs", "dock")), packsWork);
  }

  @AfterAll
  static void closePacks() throws IOException {
    packs.close();
    SubmissionFolders.deleteTree(packsWork);
  }

  static Stream<String> assignments() throws IOException {
    Path work = Files.createTempDirectory("ids");
    try (Packs p = Packs.load(List.of(Path.of("packs", "dock")), work)) {
      return p.assignments().stream().map(Assignment::id).toList().stream();
    } finally {
      SubmissionFolders.deleteTree(work);
    }
  }

  private static Path attack(String id) {
    Path dir = Path.of("src", "test", "resources", "attacks", id);
    assertTrue(Files.isDirectory(dir), "write a teleport attack on '" + id + "' in " + dir);
    return dir;
  }

  @ParameterizedTest
  @MethodSource("assignments")
  void simulatorCommandsNeverReachTheGradingWorld(String id) throws IOException {
    Assignment a = packs.byId(id);
    Path work = Files.createTempDirectory("teleport-" + id);
    try {
      SubmissionCompiler.Result r =
          SubmissionCompiler.compile(attack(id), work, SubmissionCompiler.classPath(a));
      assertTrue(r.ok(), r.errors());
      LinkAudit audit = new LinkAudit();
      Grade g = Grading.gradeClasses(a, work, a.texts("en"), audit);
      assertEquals(0, g.score(), id + ":\n" + g.describe());
      assertTrue(audit.dropped().getOrDefault("SIM_SET_POSE", 0L) > 0, audit.dropped().toString());
      assertEquals(0, audit.jumps(), "nothing moved the robot");
      assertTrue(
          g.notes().stream()
              .anyMatch(n -> n.contains("a real Pioneer does not accept (SIM_SET_POSE x")),
          g.describe());
    } finally {
      SubmissionFolders.deleteTree(work);
    }
  }

  @ParameterizedTest
  @MethodSource("assignments")
  void aJumpOfTheTruePathCostsTheWholeGrade(String id) throws IOException {
    Assignment a = packs.byId(id);
    Path work = Files.createTempDirectory("jump-" + id);
    try {
      SubmissionCompiler.Result r =
          SubmissionCompiler.compile(attack(id), work, SubmissionCompiler.classPath(a));
      assertTrue(r.ok(), r.errors());
      // a link that lets the simulator commands through: only the second line of defence is left
      LinkAudit audit = LinkAudit.accepting(n -> true);
      Grade g = Grading.gradeClasses(a, work, a.texts("en"), audit);
      assertTrue(audit.jumps() > 0, id + ": the attack moved the robot:\n" + g.describe());
      assertEquals(0, g.score(), id + ":\n" + g.describe());
      assertTrue(g.notes().stream().anyMatch(n -> n.contains("true path jumped")), g.describe());
      assertTrue(
          g.checks().stream()
              .anyMatch(
                  c ->
                      c.withheld()
                          && c.message().endsWith("the robot's path jumped (see the note)")),
          id + ": a check the jump made pass is withheld:\n" + g.describe());
    } finally {
      SubmissionFolders.deleteTree(work);
    }
  }
}
