package org.jaria.cli.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code jaria grade}'s command line: its options reach the classroom library's grading run
 * (ClassGradingTest and GradeAttackTest grade whole classes there).
 */
class GradeCommandTest {

  private record Run(int exit, String out, String err) {}

  private static Run jaria(String... args) {
    CommandLine cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(err, true));
    int exit = cli.execute(args);
    return new Run(exit, out.toString(), err.toString());
  }

  /**
   * Self-grading from the repository's root (classroom.md's command) writes the default report
   * folder there: the repository ignores it, so it never shows up as untracked work.
   */
  @Test
  void theDefaultReportFolderIsIgnoredByTheRepository() throws IOException {
    String out =
        JariaCli.commandLine()
            .getSubcommands()
            .get("grade")
            .getCommandSpec()
            .findOption("--out")
            .defaultValue();
    List<String> ignored = Files.readAllLines(Path.of("..", ".gitignore"));
    assertTrue(
        ignored.contains("/" + out + "/") || ignored.contains(out + "/"),
        "the repository's .gitignore lists " + out + "/: " + ignored);
  }

  /**
   * The command line finds grading through its CommandProvider, in the order of its help, and a
   * mistyped option of it is named as the others' are.
   */
  @Test
  void gradingJoinsTheCommandLine() {
    CommandLine cli = JariaCli.commandLine();
    List<String> names = List.copyOf(cli.getSubcommands().keySet());
    assertEquals(names.indexOf("bench") + 1, names.indexOf("grade"), names.toString());
    assertTrue(cli.getSubcommands().get("bench").getSubcommands().containsKey("grade"));
    Run typo = jaria("grade", "--jbos", "2");
    assertEquals(2, typo.exit());
    assertTrue(typo.err().contains("Did you mean --jobs?"), typo.err());
  }

  @Test
  void listsTheAssignmentsAndExplainsBadArguments(@TempDir Path tmp) {
    Run list = jaria("grade", "--list");
    assertEquals(0, list.exit());
    for (String id : List.of("square", "wall", "goals", "ball")) {
      assertTrue(list.out().contains(id + " "), list.out());
    }
    Run none = jaria("grade");
    assertEquals(2, none.exit());
    assertTrue(none.err().contains("give --assignment ID and a SUBMISSIONS folder"), none.err());
    Run unknown = jaria("grade", "--assignment", "maze", tmp.toString());
    assertEquals(2, unknown.exit());
    assertTrue(unknown.err().contains("no assignment called 'maze'"), unknown.err());
    Run noTime = jaria("grade", "-a", "square", "--timeout", "0", tmp.toString());
    assertEquals(2, noTime.exit());
    assertTrue(noTime.err().contains("--timeout and --jobs must be positive"), noTime.err());
    Run french = jaria("grade", "-a", "square", "--lang", "fr", tmp.toString());
    assertTrue(french.err().contains("--lang is en or es"), french.err());
  }

  @Test
  void gradesTheKitsSolutionWithTheGivenOptions(@TempDir Path tmp) throws IOException {
    Path subs = tmp.resolve("subs/alice");
    Files.createDirectories(subs);
    Files.copy(
        Path.of("..", "classroom", "assignments", "square", "solution", "Square.java"),
        subs.resolve("Square.java"));
    Path out = tmp.resolve("report");
    Run r =
        jaria(
            "grade",
            "-a",
            "square",
            "--unsafe",
            "--bwrap",
            tmp.resolve("no-such-bwrap").toString(),
            "--lang",
            "es",
            "-j",
            "2",
            "--timeout",
            "30",
            "-o",
            out.toString(),
            tmp.resolve("subs").toString());
    assertEquals(0, r.exit(), r.err());
    assertTrue(r.err().contains("WARNING: graded with --unsafe"), r.err());
    assertTrue(r.out().contains("Grading 1 submission(s) of 'square', 1 at a time"), r.out());
    assertTrue(r.out().contains("alice") && r.out().contains("10/10"), r.out());
    String feedback = Files.readString(out.resolve("students/alice/feedback.txt"));
    assertTrue(feedback.contains("Nota: 10/10"), feedback);
  }

  @Test
  void writesAStarterPackAndGradesWithIt(@TempDir Path tmp) throws IOException {
    Path pack = tmp.resolve("packs/parking");
    Run made = jaria("grade", "--new-pack", pack.toString());
    assertEquals(0, made.exit(), made.err());
    assertTrue(made.out().contains("test/parking/ParkingAssignmentTest.java"), made.out());
    Run again = jaria("grade", "--new-pack", pack.toString());
    assertEquals(2, again.exit());
    assertTrue(again.err().contains("already exists"), again.err());
    Run list = jaria("grade", "--pack", pack.toString(), "--list");
    assertEquals(0, list.exit(), list.err());
    assertTrue(list.out().contains("parking Drive 1 m and stop (10 points)"), list.out());
    Run notAPack = jaria("grade", "--pack", tmp.toString(), "--list");
    assertEquals(2, notAPack.exit());
    assertTrue(notAPack.err().contains("not an assignment pack"), notAPack.err());
    Path out = tmp.resolve("report");
    Run r =
        jaria(
            "grade",
            "--pack",
            pack.toString(),
            "-a",
            "parking",
            "--unsafe",
            "--bwrap",
            tmp.resolve("no-such-bwrap").toString(),
            "-o",
            out.toString(),
            pack.resolve("solution").toString());
    assertEquals(0, r.exit(), r.err());
    assertTrue(r.out().contains("10/10"), r.out());
  }

  @Test
  void thePlatformOptionsReachTheRequest() {
    CommandLine cli = JariaCli.commandLine();
    CommandLine.ParseResult p = cli.parseArgs("grade", "-a", "square", "--gradescope");
    GradeCommand g = (GradeCommand) p.subcommand().commandSpec().userObject();
    assertEquals(Path.of("/autograder/results"), g.gradescope);
    GradeCommand h =
        (GradeCommand)
            cli.parseArgs("grade", "-a", "square", "--gradescope", "out/results", "subs")
                .subcommand()
                .commandSpec()
                .userObject();
    assertEquals(Path.of("out/results"), h.gradescope);
    assertEquals(Path.of("subs"), h.submissions);
    Run both = jaria("grade", "-a", "square", "--gradescope", "r", "--github-classroom", "s");
    assertEquals(2, both.exit());
    assertTrue(both.err().contains("not both"), both.err());
  }
}
