package org.jaria.classroom.platform;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.jaria.classroom.grading.GradeReport;
import org.jaria.classroom.grading.GradeRequest;
import org.jaria.classroom.grading.Grader;

/**
 * Hands a grade to the platform a {@link GradeRequest} names: Gradescope's results.json, or GitHub
 * Classroom's reporter result (and the feedback on standard output); nothing for a local grading.
 */
public final class Platforms {

  private Platforms() {}

  /**
   * Writes what {@code r}'s platform reads about {@code student}'s graded result, whose feedback is
   * in {@code report}, printing the feedback on {@code o} for GitHub Classroom.
   */
  public static void graded(
      GradeRequest r, GradeReport report, Grader.Result student, PrintWriter o) throws IOException {
    switch (r.platform()) {
      case LOCAL -> {}
      case GRADESCOPE -> {
        String feedback = report.feedback(student);
        write(resultsFile(r), GradescopeResults.of(student, feedback));
        o.print(feedback);
        o.flush();
      }
      case GITHUB_CLASSROOM -> {
        o.print(report.feedback(student));
        o.flush();
        githubOutput(r, GithubClassroomResult.json(student), o);
      }
    }
  }

  /**
   * Writes what {@code r}'s platform reads when the grading was refused for {@code why} (the result
   * line for GitHub Classroom on {@code o} if there is no output file).
   */
  public static void refused(GradeRequest r, String why, PrintWriter o) throws IOException {
    switch (r.platform()) {
      case LOCAL -> {}
      case GRADESCOPE -> write(resultsFile(r), GradescopeResults.refused(why, r.lang()));
      case GITHUB_CLASSROOM -> githubOutput(r, GithubClassroomResult.refused(why), o);
    }
  }

  private static Path resultsFile(GradeRequest r) {
    Path dir = r.platformOut() == null ? GradeRequest.GRADESCOPE_RESULTS : r.platformOut();
    return dir.resolve("results.json");
  }

  private static void write(Path file, String text) throws IOException {
    Files.createDirectories(file.toAbsolutePath().getParent());
    Files.writeString(file, text, StandardCharsets.UTF_8);
  }

  /** Appends the result line to the GitHub Actions output file, or prints it if there is none. */
  private static void githubOutput(GradeRequest r, String json, PrintWriter o) throws IOException {
    String line = GithubClassroomResult.outputLine(json) + "\n";
    if (r.platformOut() == null) {
      o.print(line);
      o.flush();
    } else {
      Files.writeString(
          r.platformOut(),
          line,
          StandardCharsets.UTF_8,
          StandardOpenOption.CREATE,
          StandardOpenOption.APPEND);
    }
  }
}
