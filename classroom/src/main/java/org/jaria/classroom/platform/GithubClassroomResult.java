package org.jaria.classroom.platform;

import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.List;
import org.jaria.classroom.grading.Check;
import org.jaria.classroom.grading.Grader;
import org.jaria.classroom.grading.Neutral;

/**
 * A grade as GitHub Classroom's autograding reporter reads it: the JSON its graders hand on (a
 * version, a status of pass, fail or error, the maximum score, and one test per check with its
 * name, status, score and message), base64-encoded as a step's {@code result} output. The reporter
 * adds up the tests' scores, so a student gets partial credit check by check.
 */
public final class GithubClassroomResult {

  private GithubClassroomResult() {}

  /** The reporter's JSON for {@code r}. */
  public static String json(Grader.Result r) {
    boolean full = r.grade().score() == r.grade().maxScore() && r.grade().maxScore() > 0;
    StringBuilder sb = new StringBuilder("{\"version\":1,\"status\":\"");
    sb.append(full ? "pass" : "fail")
        .append("\",\"max_score\":")
        .append(r.grade().maxScore())
        .append(",\"tests\":[");
    List<Check> checks = r.grade().checks();
    for (int i = 0; i < checks.size(); i++) {
      Check c = checks.get(i);
      sb.append(i == 0 ? "" : ",")
          .append("{\"name\":")
          .append(Json.string(c.name()))
          .append(",\"status\":\"")
          .append(c.passed() ? "pass" : "fail")
          .append("\",\"score\":")
          .append(c.earned())
          .append(",\"message\":")
          .append(Json.string(Neutral.text(c.message())))
          .append(",\"test_code\":\"\",\"filename\":\"\",\"line_no\":0,\"execution_time\":\"\"}");
    }
    return sb.append("]}").toString();
  }

  /** The reporter's JSON for a submission that could not be graded. */
  public static String refused(String why) {
    return "{\"version\":1,\"status\":\"error\",\"max_score\":0,\"tests\":[{\"name\":\"grading\","
        + "\"status\":\"error\",\"score\":0,\"message\":"
        + Json.string(Neutral.text(why))
        + ",\"test_code\":\"\",\"filename\":\"\",\"line_no\":0,\"execution_time\":\"\"}]}";
  }

  /** The line a step writes to {@code $GITHUB_OUTPUT}: {@code result=} and the encoded JSON. */
  public static String outputLine(String json) {
    return "result=" + Base64.getEncoder().encodeToString(json.getBytes(StandardCharsets.UTF_8));
  }
}
