package org.jaria.cli.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.jaria.classroom.sandbox.Sandbox;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The classroom guide's "Write your own assignment" and "Grading on Gradescope / GitHub Classroom"
 * sections run as written: each {@code ./jaria} line in them, in order, with the folders they name
 * that are not in JAria (and {@code /autograder}) in a temporary folder; and the {@code jaria
 * grade} lines of the Gradescope scripts and the GitHub Classroom workflow the section hands out.
 */
@Tag("slow")
class JariaDocsGradeTest {

  private final Path root = Path.of("..").toAbsolutePath().normalize();

  private record Run(int exit, String out) {}

  /** The {@code ./jaria} lines of the guide's section {@code title}, in order. */
  private List<String> commands(String title) throws IOException {
    String doc = Files.readString(root.resolve("docs/classroom.md"), StandardCharsets.UTF_8);
    int from = doc.indexOf("\n## " + title + "\n");
    assertTrue(from >= 0, "no section '" + title + "' in docs/classroom.md");
    int to = doc.indexOf("\n## ", from + 4);
    String section = doc.substring(from, to < 0 ? doc.length() : to);
    List<String> out = new ArrayList<>();
    for (String l : section.split("\n", -1)) {
      if (l.startsWith("    ./jaria ")) {
        out.add(l.strip());
      }
    }
    return out;
  }

  /**
   * {@code line}'s arguments, its folders outside JAria (and /autograder) moved into {@code tmp}.
   */
  private String[] args(String line, Path tmp, int n) {
    List<String> words = new ArrayList<>(Arrays.asList(line.split("\\s+")));
    words.remove(0); // ./jaria, or jaria/jaria in the workflow
    List<String> out = new ArrayList<>();
    for (String w : words) {
      if (w.startsWith("/autograder")) {
        out.add(tmp + w);
      } else if (!w.startsWith("-") && w.contains("/")) {
        Path inRepo = root.resolve(w);
        out.add(Files.exists(inRepo) ? inRepo.toString() : tmp.resolve(w).toString());
      } else if (w.equals("submission")) {
        out.add(tmp.resolve(w).toString());
      } else {
        out.add(w);
      }
    }
    boolean grades = !out.contains("--new-pack") && !out.contains("--list");
    if (grades && !out.contains("--out") && !out.contains("-o")) {
      out.add(1, "--out");
      out.add(2, tmp.resolve("report-" + n).toString());
    }
    return out.toArray(String[]::new);
  }

  private static Run jaria(String... args) {
    CommandLine cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(out, true));
    int exit = cli.execute(args);
    return new Run(exit, out.toString());
  }

  @Test
  void writeYourOwnAssignmentRunsAsWritten(@TempDir Path tmp) throws IOException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    List<String> lines = commands("Write your own assignment");
    assertTrue(lines.size() >= 4, lines.toString());
    int n = 0;
    for (String line : lines) {
      Run r = jaria(args(line, tmp, n++));
      assertEquals(0, r.exit(), line + "\n" + r.out());
      if (line.contains(" classroom/packs/dock/solution") || line.contains("parking/solution")) {
        assertTrue(r.out().contains("10/10  GRADED"), line + "\n" + r.out());
      }
    }
    assertTrue(
        Files.isRegularFile(tmp.resolve("my-packs/parking/src/parking/ParkingAssignment.java")));
  }

  @Test
  void gradescopeAndGithubClassroomRunAsWritten(@TempDir Path tmp)
      throws IOException, InterruptedException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    String starter =
        Files.readString(root.resolve("classroom/assignments/square/starter/Square.java"));
    for (Path dir : List.of(tmp.resolve("autograder/submission"), tmp.resolve("submission"))) {
      Files.createDirectories(dir);
      Files.writeString(dir.resolve("Square.java"), starter);
    }
    List<String> lines = new ArrayList<>(commands("Grading on Gradescope / GitHub Classroom"));
    assertEquals(2, lines.size(), lines.toString());
    lines.add(gradeLine(root.resolve("docs/classroom/gradescope/run_autograder"), "./jaria grade"));
    lines.add(gradeLine(root.resolve("docs/classroom/github-classroom.yml"), "jaria/jaria grade"));
    int n = 0;
    for (String line : lines) {
      Files.deleteIfExists(tmp.resolve("autograder/results/results.json"));
      Run r = jaria(args(line, tmp, n++));
      assertEquals(0, r.exit(), line + "\n" + r.out());
      assertTrue(r.out().contains("Score: 5/10\n"), line + "\n" + r.out());
      if (line.contains("--gradescope")) {
        String json = Files.readString(tmp.resolve("autograder/results/results.json"));
        assertTrue(json.contains("\"score\": 5,"), json);
      } else if (System.getenv("GITHUB_OUTPUT") == null) {
        assertTrue(r.out().contains("\nresult="), r.out());
      }
    }
    for (String script : List.of("setup.sh", "run_autograder")) {
      Process p =
          new ProcessBuilder(
                  "bash",
                  "-n",
                  root.resolve("docs/classroom/gradescope").resolve(script).toString())
              .redirectErrorStream(true)
              .start();
      assertTrue(p.waitFor(30, TimeUnit.SECONDS));
      assertEquals(
          0,
          p.exitValue(),
          script + ": " + new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
    }
  }

  private static String gradeLine(Path file, String prefix) throws IOException {
    return Files.readAllLines(file).stream()
        .map(String::strip)
        .map(l -> l.startsWith("run: ") ? l.substring(5) : l)
        .filter(l -> l.startsWith(prefix))
        .findFirst()
        .orElseThrow(() -> new AssertionError("no '" + prefix + "' line in " + file));
  }
}
