package org.jaria.classroom.classgrading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A teacher's grading run end to end ({@code jaria grade} without its command line): a folder with
 * a good, a bad, a non-compiling and an endlessly looping submission is graded, each in a JVM of
 * its own, and every one gets its grade.
 */
@Tag("slow")
class ClassGradingTest {

  private static void write(Path dir, String file, String text) throws IOException {
    Files.createDirectories(dir);
    Files.writeString(dir.resolve(file), text, StandardCharsets.UTF_8);
  }

  private static String kit(String which) throws IOException {
    return Files.readString(Path.of("assignments", "square", which, "Square.java"));
  }

  private record Run(int exit, String out, String err) {}

  private static Run grade(GradeRequest request) throws IOException {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    int exit = ClassGrading.grade(request, new PrintWriter(out), new PrintWriter(err));
    return new Run(exit, out.toString(), err.toString());
  }

  @Test
  void gradesEverySubmissionWhateverTheOthersDo(@TempDir Path tmp) throws IOException {
    Path subs = tmp.resolve("submissions");
    write(subs.resolve("alice"), "Square.java", kit("solution"));
    write(subs.resolve("bob"), "Square.java", kit("starter"));
    write(
        subs.resolve("carol"),
        "Square.java",
        """
        import org.jaria.classroom.RobotProgram;
        import org.jaria.robot.ArRobot;
        public class Square implements RobotProgram {
          public void run(ArRobot robot) {
            robot.mve(2000);
          }
        }
        """);
    write(
        subs.resolve("dave"),
        "Square.java",
        """
        import org.jaria.classroom.RobotProgram;
        import org.jaria.robot.ArRobot;
        public class Square implements RobotProgram {
          public Square() throws InterruptedException {
            Thread.sleep(Long.MAX_VALUE);
          }
          public void run(ArRobot robot) {}
        }
        """);
    Path out = tmp.resolve("report");
    // A good submission's JVM needs about 2 s; dave's constructor never returns and is stopped at
    // the limit. It sleeps rather than spins, so it costs no processor time while the limit runs
    // out (GradeAttackTest's spinning constructor shows the processor-time side).
    Run r = grade(GradeRequest.of("square", subs, out).withTimeout(Duration.ofSeconds(12)));
    assertEquals(0, r.exit(), r.err());

    Map<String, String> rows =
        r.out()
            .lines()
            .filter(l -> l.matches("^(alice|bob|carol|dave) .*"))
            .collect(Collectors.toMap(l -> l.substring(0, l.indexOf(' ')), l -> l, (a, b) -> a));
    assertTrue(rows.get("alice").matches("alice +10/10 +GRADED .*"), r.out());
    assertTrue(rows.get("bob").matches("bob +\\d/10 +GRADED .*corner 2.*"), r.out());
    assertTrue(rows.get("carol").matches("carol +0/10 +COMPILE_ERROR .*"), r.out());
    assertTrue(rows.get("dave").matches("dave +0/10 +TIMEOUT .*"), r.out());
    assertTrue(r.out().contains("[4/4] "), "progress is printed:\n" + r.out());
    assertTrue(
        r.out().contains("Square.java:5: error: cannot find symbol"),
        "the compile error is shown with its line:\n" + r.out());

    String md = Files.readString(out.resolve("report.md"));
    assertTrue(md.contains("| alice | 10/10 | GRADED | - |"), md);
    String html = Files.readString(out.resolve("report.html"));
    assertTrue(html.contains("<td>dave</td>") || html.contains(">dave</a>"), html);
    assertTrue(Files.readString(out.resolve("report.txt")).contains("[FAIL] compiles"));
    assertTrue(
        Files.readString(out.resolve("students/dave/feedback.txt")).contains("Status: TIMEOUT"));

    // bob hands in the solution: re-grade only him into the same report, in Spanish
    write(subs.resolve("bob"), "Square.java", kit("solution"));
    Run again = grade(GradeRequest.of("square", subs, out).onlyStudent("bob").inLanguage("es"));
    assertEquals(0, again.exit(), again.err());
    assertTrue(again.out().contains("[1/1] bob "), again.out());
    String csv = Files.readString(out.resolve("gradebook.csv"));
    assertTrue(csv.contains("\nalice,10,10,GRADED,"), csv);
    assertTrue(csv.contains("\nbob,10,10,GRADED,"), csv);
    assertTrue(csv.contains("\ncarol,0,10,COMPILE_ERROR,"), csv);
    assertTrue(csv.contains("\ndave,0,10,TIMEOUT,"), csv);
    String feedback = Files.readString(out.resolve("students/bob/feedback.txt"));
    assertTrue(feedback.contains("Nota: 10/10"), feedback);
    assertTrue(feedback.contains("Tu programa se ejecutó"), feedback);
    // the checks too are in Spanish
    assertTrue(feedback.contains("esquina 1 alcanzada"), feedback);
    assertFalse(feedback.contains("corner 1 reached"), feedback);
    assertTrue(Files.readString(out.resolve("report.md")).contains("| Estudiante | Nota |"));
  }

  @Test
  void withoutBubblewrapItRefusesToGradeAndWritesNothing(@TempDir Path tmp) throws IOException {
    write(tmp.resolve("subs/alice"), "Square.java", kit("solution"));
    Path out = tmp.resolve("report");
    String missing = tmp.resolve("no-such-bwrap").toString();
    Run r = grade(GradeRequest.of("square", tmp.resolve("subs"), out).withBwrap(Path.of(missing)));
    assertEquals(2, r.exit(), r.out() + r.err());
    assertTrue(r.err().contains(missing + " is missing"), r.err());
    assertTrue(r.err().contains("Refusing to grade; --unsafe grades anyway"), r.err());
    assertFalse(Files.exists(out), "nothing is graded, so no report folder");
  }

  @Test
  void unsafeGradingWarnsOnEveryReport(@TempDir Path tmp) throws IOException {
    write(tmp.resolve("subs/alice"), "Square.java", kit("solution"));
    Path out = tmp.resolve("report");
    // --unsafe grades where bubblewrap is missing
    Run r =
        grade(
            GradeRequest.of("square", tmp.resolve("subs"), out)
                .withoutIsolation()
                .withBwrap(tmp.resolve("no-such-bwrap")));
    assertEquals(0, r.exit(), r.err());
    assertTrue(r.err().contains("WARNING: graded with --unsafe"), r.err());
    assertTrue(r.out().contains("alice") && r.out().contains("10/10"), r.out());
    for (String f :
        List.of("report.txt", "report.md", "report.html", "students/alice/feedback.txt")) {
      assertTrue(Files.readString(out.resolve(f)).contains("WARNING: graded with --unsafe"), f);
    }
  }

  @Test
  void refusesRequestsItCannotCarryOutAndSaysWhatToChange(@TempDir Path tmp) throws IOException {
    Path out = tmp.resolve("report");
    Run unknown = grade(GradeRequest.of("maze", tmp, out));
    assertEquals(ClassGrading.REFUSED, unknown.exit());
    assertTrue(unknown.err().contains("no assignment called 'maze'"), unknown.err());
    Run empty = grade(GradeRequest.of("square", tmp, out));
    assertEquals(ClassGrading.REFUSED, empty.exit());
    assertTrue(empty.err().contains("no submissions in"), empty.err());
    write(tmp.resolve("subs/alice"), "Square.java", kit("solution"));
    GradeRequest ok = GradeRequest.of("square", tmp.resolve("subs"), out);
    Run inside = grade(GradeRequest.of("square", tmp.resolve("subs"), tmp.resolve("subs/r")));
    assertTrue(inside.err().contains("put --out outside the submissions folder"), inside.err());
    Run noTime = grade(ok.withTimeout(Duration.ZERO));
    assertTrue(noTime.err().contains("--timeout and --jobs must be positive"), noTime.err());
    Run noJobs = grade(ok.withJobs(0));
    assertEquals(ClassGrading.REFUSED, noJobs.exit());
    Run french = grade(ok.inLanguage("fr"));
    assertTrue(french.err().contains("--lang is en or es"), french.err());
    Run nobody = grade(ok.onlyStudent("zoe").withoutIsolation());
    assertTrue(nobody.err().contains("no submission called 'zoe'"), nobody.err());
    assertFalse(Files.exists(out), "nothing is graded, so no report folder");
  }
}
