package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.jaria.classroom.link.LinkAudit;
import org.junit.jupiter.api.Test;

/** The grader's last word on a grade: drops become notes, a jump of the true path costs it all. */
class IntegrityTest {

  private final Grade full =
      new Grade(
          "square",
          List.of(
              Check.pass("corner 1 reached", 6, "passed within 0 mm"),
              Check.fail("stops at the end", 4, "still moving")));

  @Test
  void aCleanLinkChangesNothing() {
    assertEquals(full, Integrity.apply(full, new LinkAudit(), Texts.english()));
  }

  @Test
  void droppedPacketsAreCountedInANoteAndCostNothing() {
    LinkAudit a = new LinkAudit();
    a.dropped("SIM_SET_POSE");
    a.dropped("SIM_SET_POSE");
    a.dropped("SIM_EXIT");
    a.garbage(7);
    Grade g = Integrity.apply(full, a, Texts.english());
    assertEquals(6, g.score());
    assertEquals(2, g.notes().size(), g.notes().toString());
    assertTrue(
        g.notes().get(0).startsWith("the grading world dropped 3 packet(s)"), g.notes().get(0));
    assertTrue(g.notes().get(0).contains("(SIM_EXIT x1, SIM_SET_POSE x2)"), g.notes().get(0));
    assertTrue(g.notes().get(1).contains("7 byte(s)"), g.notes().get(1));
  }

  @Test
  void aJumpWithholdsEveryPassedCheckAndSaysWhereItJumped() {
    LinkAudit a = new LinkAudit();
    a.jump(new LinkAudit.Jump(2.5, 0, 0, 2000, 0, 2000, 0));
    Grade g = Integrity.apply(full, a, Texts.of("es"));
    assertEquals(0, g.score());
    Check c = g.checks().get(0);
    assertTrue(c.withheld(), c.toString());
    assertTrue(c.message().endsWith("la trayectoria del robot saltó (mira la nota)"), c.message());
    assertTrue(g.checks().get(1).message().equals("still moving"), "a failure stays as it was");
    assertTrue(g.notes().get(0).contains("saltó 2.00 m"), g.notes().get(0));
    assertTrue(g.notes().get(0).contains("de (0, 0) a (2000, 0)"), g.notes().get(0));
  }
}
