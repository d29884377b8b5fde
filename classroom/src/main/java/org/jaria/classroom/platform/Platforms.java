package org.jaria.classroom.platform;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.jaria.classroom.grading.GradeReport;
import org.jaria.classroom.grading.Grader;

/**
 * Hands a grade to a {@link Platform}: Gradescope's results.json, or GitHub Classroom's reporter
 * result (and the feedback on standard output); nothing for a local grading. It takes the platform
 * and where its results go as plain values, so it knows nothing of the request that named them.
 */
public final class Platforms {

  /** Where Gradescope's autograder wants results.json. */
  public static final Path GRADESCOPE_RESULTS = Path.of("/autograder/results");

  private Platforms() {}

  /**
   * Writes what {@code platform} reads about {@code student}'s graded result, whose feedback is in
   * {@code report}, printing the feedback on {@code o} for GitHub Classroom.
   *
   * @param out Gradescope's results folder, or the GitHub Actions output file (null: Gradescope's
   *     usual folder, or standard output)
   */
  public static void graded(
      Platform platform, Path out, GradeReport report, Grader.Result student, PrintWriter o)
      throws IOException {
    switch (platform) {
      case LOCAL -> {}
      case GRADESCOPE -> {
        String feedback = report.feedback(student);
        write(resultsFile(out), GradescopeResults.of(student, feedback));
        o.print(feedback);
        o.flush();
      }
      case GITHUB_CLASSROOM -> {
        o.print(report.feedback(student));
        o.flush();
        githubOutput(out, GithubClassroomResult.json(student), o);
      }
    }
  }

  /**
   * Writes what {@code platform} reads when the grading was refused for {@code why}, in language
   * {@code lang} (the result line for GitHub Classroom on {@code o} if {@code out} is null).
   */
  public static void refused(Platform platform, Path out, String lang, String why, PrintWriter o)
      throws IOException {
    switch (platform) {
      case LOCAL -> {}
      case GRADESCOPE -> write(resultsFile(out), GradescopeResults.refused(why, lang));
      case GITHUB_CLASSROOM -> githubOutput(out, GithubClassroomResult.refused(why), o);
    }
  }

  private static Path resultsFile(Path out) {
    return (out == null ? GRADESCOPE_RESULTS : out).resolve("results.json");
  }

  private static void write(Path file, String text) throws IOException {
    Files.createDirectories(file.toAbsolutePath().getParent());
    Files.writeString(file, text, StandardCharsets.UTF_8);
  }

  /** Appends the result line to the GitHub Actions output file, or prints it if there is none. */
  private static void githubOutput(Path out, String json, PrintWriter o) throws IOException {
    String line = GithubClassroomResult.outputLine(json) + "\n";
    if (out == null) {
      o.print(line);
      o.flush();
    } else {
      Files.writeString(
          out, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }
  }
}
