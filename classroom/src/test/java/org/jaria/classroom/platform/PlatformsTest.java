package org.jaria.classroom.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.sandbox.Sandbox;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Grading where classes are graded, in a container-like folder layout: Gradescope's results.json
 * and GitHub Classroom's reporter result give the student the same grade as a local {@code jaria
 * grade}, and the same feedback byte for byte.
 */
@Tag("slow")
class PlatformsTest {

  private static String starter() throws IOException {
    return Files.readString(Path.of("assignments/square/starter/Square.java"));
  }

  private record Run(int exit, String out, String err) {}

  private static Run grade(GradeRequest r) throws IOException {
    StringWriter o = new StringWriter();
    StringWriter e = new StringWriter();
    int exit = ClassGrading.grade(r, new PrintWriter(o), new PrintWriter(e));
    return new Run(exit, o.toString(), e.toString());
  }

  /** The feedback a local grading gives the student whose folder is named "submission". */
  private static String localFeedback(Path tmp) throws IOException {
    Path cls = tmp.resolve("class");
    Files.createDirectories(cls.resolve("submission"));
    Files.writeString(cls.resolve("submission/Square.java"), starter());
    Run r =
        grade(
            GradeRequest.of("square", cls, tmp.resolve("local"))
                .withTimeout(Duration.ofSeconds(30))
                .withScratchRoot(tmp.resolve("scratch")));
    assertEquals(0, r.exit(), r.err());
    return Files.readString(
        tmp.resolve("local/students/submission/feedback.txt"), StandardCharsets.UTF_8);
  }

  /** A JSON string field's value, unescaped (the few escapes Json writes). */
  static String field(String json, String name) {
    Matcher m = Pattern.compile("\"" + name + "\": ?\"((?:[^\"\\\\]|\\\\.)*)\"").matcher(json);
    assertTrue(m.find(), name + " in " + json);
    String s = m.group(1);
    StringBuilder sb = new StringBuilder();
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (c != '\\') {
        sb.append(c);
        continue;
      }
      char n = s.charAt(++i);
      switch (n) {
        case 'n' -> sb.append('\n');
        case 't' -> sb.append('\t');
        case 'r' -> sb.append('\r');
        case 'u' -> {
          sb.append((char) Integer.parseInt(s.substring(i + 1, i + 5), 16));
          i += 4;
        }
        default -> sb.append(n);
      }
    }
    return sb.toString();
  }

  @Test
  void gradescopeGetsTheLocalGradeAndFeedback(@TempDir Path tmp) throws IOException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    String local = localFeedback(tmp);
    // the autograder's folders, as Gradescope's container has them
    Path ag = tmp.resolve("autograder");
    Files.createDirectories(ag.resolve("submission"));
    Files.writeString(ag.resolve("submission/Square.java"), starter());
    Run r =
        grade(
            GradeRequest.of("square", ag.resolve("submission"), ag.resolve("grading-report"))
                .withTimeout(Duration.ofSeconds(30))
                .withScratchRoot(tmp.resolve("scratch"))
                .reportingTo(Platform.GRADESCOPE, ag.resolve("results")));
    assertEquals(0, r.exit(), r.err());
    String json = Files.readString(ag.resolve("results/results.json"), StandardCharsets.UTF_8);
    assertTrue(json.contains("\"score\": 5,"), json);
    assertEquals(local, field(json, "output"), "the same feedback, byte for byte");
    assertTrue(
        json.contains(
            "{\"number\": \"2\", \"name\": \"corner 1 reached\", \"score\": 2, \"max_score\": 2,"
                + " \"status\": \"passed\", \"visibility\": \"visible\", \"output\": \"passed"),
        json);
    assertTrue(json.contains("\"name\": \"corner 2 reached\", \"score\": 0, \"max_score\": 2"));
    assertEquals(local, r.out(), "what run_autograder prints is the feedback too");
  }

  @Test
  void githubClassroomGetsTheLocalGradeAndFeedback(@TempDir Path tmp) throws IOException {
    assumeTrue(Sandbox.whyUnavailable().isEmpty(), "bubblewrap is not usable here");
    String local = localFeedback(tmp);
    Path repo = tmp.resolve("workspace/submission");
    Files.createDirectories(repo.resolve("src"));
    Files.writeString(repo.resolve("src/Square.java"), starter());
    Files.writeString(repo.resolve("README.md"), "# my square");
    Path output = tmp.resolve("github_output");
    Run r =
        grade(
            GradeRequest.of("square", repo, tmp.resolve("workspace/grading-report"))
                .withTimeout(Duration.ofSeconds(30))
                .withScratchRoot(tmp.resolve("scratch"))
                .reportingTo(Platform.GITHUB_CLASSROOM, output));
    assertEquals(0, r.exit(), r.err());
    assertEquals(local, r.out(), "the step's log is the feedback, byte for byte");
    String line = Files.readString(output).strip();
    assertTrue(line.startsWith("result="), line);
    String json = new String(Base64.getDecoder().decode(line.substring(7)), StandardCharsets.UTF_8);
    assertTrue(json.startsWith("{\"version\":1,\"status\":\"fail\",\"max_score\":10,"), json);
    int sum = 0;
    Matcher m = Pattern.compile("\"score\":(\\d+)").matcher(json);
    while (m.find()) {
      sum += Integer.parseInt(m.group(1));
    }
    assertEquals(5, sum, "the reporter adds up the tests' scores: " + json);
    assertTrue(json.contains("{\"name\":\"corner 1 reached\",\"status\":\"pass\",\"score\":2,"));
  }

  @Test
  void aRefusedGradingStillTellsThePlatformWhy(@TempDir Path tmp) throws IOException {
    Path ag = tmp.resolve("autograder");
    Files.createDirectories(ag.resolve("submission"));
    Files.writeString(ag.resolve("submission/Square.java"), "class Square {}");
    Run r =
        grade(
            GradeRequest.of("square", ag.resolve("submission"), ag.resolve("grading-report"))
                .withBwrap(tmp.resolve("no-bwrap"))
                .reportingTo(Platform.GRADESCOPE, ag.resolve("results")));
    assertEquals(ClassGrading.REFUSED, r.exit());
    String json = Files.readString(ag.resolve("results/results.json"));
    assertTrue(json.contains("\"score\": 0,"), json);
    assertTrue(
        field(json, "output").startsWith("The autograder could not grade your submission: cannot"),
        json);
    Path output = tmp.resolve("github_output");
    Run gh =
        grade(
            GradeRequest.of("square", ag.resolve("submission"), ag.resolve("grading-report"))
                .withBwrap(tmp.resolve("no-bwrap"))
                .reportingTo(Platform.GITHUB_CLASSROOM, output));
    assertEquals(ClassGrading.REFUSED, gh.exit());
    String b64 = Files.readString(output).strip().substring("result=".length());
    String ghJson = new String(Base64.getDecoder().decode(b64), StandardCharsets.UTF_8);
    assertTrue(ghJson.contains("\"status\":\"error\""), ghJson);
  }

  @Test
  void jsonStringsEscapeEveryControlCharacter() {
    assertEquals("\"a\\\"b\\\\c\\nd\\u001be\"", Json.string("a\"b\\c\nd\u001be"));
  }
}
