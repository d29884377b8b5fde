package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import org.jaria.classroom.square.SquareAssignment;
import org.junit.jupiter.api.Test;

/** The reports at their edges, as a teacher found them: one fixed set of columns, no cut text. */
class GradeReportTest {

  private final SquareAssignment square = new SquareAssignment();

  private Grader.Result graded(String student, Texts t, boolean pass) {
    List<Check> checks = new java.util.ArrayList<>();
    for (String name : square.checkNames(t)) {
      checks.add(new Check(name, 1, pass, "why"));
    }
    return new Grader.Result(student, Status.GRADED, new Grade("square", checks), 1, null);
  }

  @Test
  void theGradebookHasTheAssignmentsColumnsWhateverTheLanguageAndWhoeverRan() {
    Grader.Result ana = graded("ana", Texts.english(), true);
    Grader.Result bob = graded("bob", Texts.of("es"), false); // re-graded with --lang es
    Grader.Result carl =
        new Grader.Result(
            "carl",
            Status.COMPILE_ERROR,
            new Grade("square", List.of(Check.fail("compiles", 10, "no"))),
            1,
            null);
    String header =
        "student,score,max,status,el programa termina,esquina 1 alcanzada,esquina 2 alcanzada,"
            + "esquina 3 alcanzada,de vuelta al inicio,se detiene al final,solo órdenes de"
            + " movimiento\n";
    String csv = new GradeReport(square, List.of(ana, bob, carl), "es", false, null).csv();
    assertTrue(csv.startsWith(header), csv);
    assertTrue(csv.contains("\nana,7,7,GRADED,1,1,1,1,1,1,1\n"), csv);
    assertTrue(csv.contains("\nbob,0,7,GRADED,0,0,0,0,0,0,0\n"), csv);
    assertTrue(csv.contains("\ncarl,0,10,COMPILE_ERROR,,,,,,,\n"), csv);
    // only carl ran: the columns are the same
    String alone = new GradeReport(square, List.of(carl), "es", false, null).csv();
    assertTrue(alone.startsWith(header), alone);
    String english = new GradeReport(square, List.of(bob), "en", false, null).csv();
    assertTrue(english.startsWith("student,score,max,status,program ends,corner 1 reached"));
    assertTrue(english.contains("\nbob,0,7,GRADED,0,0,0,0,0,0,0\n"), english);
  }

  @Test
  void reportsSayWhenWhatAndHowAndCutNothing() {
    String longWhy = "x".repeat(300) + " END";
    Grader.Result one =
        new Grader.Result(
            "ana",
            Status.GRADED,
            new Grade("square", List.of(Check.fail("corner 1 reached", 10, longWhy))),
            1,
            null);
    GradeReport r =
        new GradeReport(
            square,
            List.of(one),
            "en",
            false,
            new GradeReport.RunInfo("2026-03-05 14:02 UTC", "1.2.3", Duration.ofSeconds(20), 2));
    String text = r.text();
    assertTrue(
        text.contains(
            "Graded 2026-03-05 14:02 UTC by JAria 1.2.3: assignment square, timeout 20 s per"
                + " student, 2 jobs"),
        text);
    assertTrue(text.contains("1 student, mean 0.0/10"), text);
    assertTrue(text.contains(longWhy + "\n"), "the first problem is whole:\n" + text);
    assertTrue(r.markdown().contains("JAria 1.2.3"), r.markdown());
    assertTrue(r.html().contains("JAria 1.2.3"));
  }

  @Test
  void aStudentsNameAndOutputAreNeutralisedInEveryReport() {
    String name = "=cmd|' /C calc'!A0\u001b[31m";
    String msg = "your program threw X (<b>hi</b>\r\n=1+1\u001b]0;x\u0007)";
    Grader.Result r =
        new Grader.Result(
            name,
            Status.GRADED,
            new Grade("square", List.of(Check.fail("program ends", 10, msg))),
            1,
            null);
    GradeReport report = new GradeReport(square, List.of(r), "en", false, null);
    for (String s : List.of(report.text(), report.feedback(r), report.markdown(), report.csv())) {
      assertFalse(s.contains("\u001b"), s);
      assertFalse(s.contains("\r"), s);
      assertFalse(s.contains("\u0007"), s);
    }
    assertTrue(report.csv().contains("\n\"'=cmd|' /C calc'!A0?[31m\",0,10"), report.csv());
    assertTrue(report.csv().lines().noneMatch(l -> l.startsWith("=")), report.csv());
    assertFalse(report.markdown().contains("<b>"), report.markdown());
    assertFalse(report.html().contains("<b>hi"), report.html());
  }

  @Test
  void withheldChecksAreNotCountedAsTheClassesFailures() {
    Grader.Result r =
        new Grader.Result(
            "ana",
            Status.GRADED,
            new Grade(
                "square",
                List.of(
                    Check.fail("program ends", 1, "busy"),
                    Check.withheld("corner 1 reached", 2, "not judged"))),
            1,
            null);
    ClassStats s = ClassStats.of(List.of(r), 10);
    assertEquals(java.util.Map.of("program ends", 1), s.mostFailed());
  }
}
