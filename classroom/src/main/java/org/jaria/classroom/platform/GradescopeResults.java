package org.jaria.classroom.platform;

import java.util.List;
import java.util.Locale;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Grader;
import org.jaria.classroom.grading.Neutral;

/**
 * A grade as Gradescope's autograder reads it ({@code /autograder/results/results.json}): the
 * score, the whole feedback as the submission's output (the same text as {@code feedback.txt}), and
 * one test per check with its name, score, maximum, status and message, all visible to the student.
 */
public final class GradescopeResults {

  private GradescopeResults() {}

  /** The results.json of {@code r}, whose feedback text is {@code feedback}. */
  public static String of(Grader.Result r, String feedback) {
    StringBuilder sb = new StringBuilder("{\n");
    sb.append("  \"score\": ").append(r.grade().score()).append(",\n");
    sb.append("  \"execution_time\": ").append(Math.round(Math.ceil(r.seconds()))).append(",\n");
    sb.append("  \"output\": ").append(Json.string(feedback)).append(",\n");
    sb.append("  \"output_format\": \"text\",\n");
    sb.append("  \"test_output_format\": \"text\",\n");
    sb.append("  \"visibility\": \"visible\",\n");
    sb.append("  \"stdout_visibility\": \"hidden\",\n");
    sb.append("  \"tests\": [");
    List<Check> checks = r.grade().checks();
    for (int i = 0; i < checks.size(); i++) {
      Check c = checks.get(i);
      sb.append(i == 0 ? "\n" : ",\n")
          .append("    {\"number\": \"")
          .append(i + 1)
          .append("\", \"name\": ")
          .append(Json.string(c.name()))
          .append(", \"score\": ")
          .append(c.earned())
          .append(", \"max_score\": ")
          .append(c.points())
          .append(", \"status\": \"")
          .append(c.passed() ? "passed" : "failed")
          .append("\", \"visibility\": \"visible\", \"output\": ")
          .append(Json.string(Neutral.text(c.message())))
          .append('}');
    }
    sb.append(checks.isEmpty() ? "]\n" : "\n  ]\n").append("}\n");
    return sb.toString();
  }

  /** The results.json that tells the student their submission could not be graded, and why. */
  public static String refused(String why, String lang) {
    String output =
        "es".equals(lang)
            ? "El evaluador no pudo evaluar tu entrega: " + why + ". Avisa a tu profesor."
            : "The autograder could not grade your submission: " + why + ". Tell your teacher.";
    return String.format(
        Locale.ROOT,
        """
        {
          "score": 0,
          "output": %s,
          "output_format": "text",
          "visibility": "visible",
          "tests": []
        }
        """,
        Json.string(Neutral.text(output)));
  }
}
