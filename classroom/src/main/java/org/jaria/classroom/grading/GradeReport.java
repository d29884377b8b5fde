package org.jaria.classroom.grading;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A grading run as a teacher reads it: a plain-text table, Markdown, an HTML page, a CSV gradebook
 * and one feedback text per student, in English or Spanish ({@code lang} "en" or "es"). Whatever
 * came from a student (names, what their program printed or threw) is neutralised for each format
 * ({@link Neutral}).
 */
public final class GradeReport {

  /**
   * How the run was made, for the reports' heading.
   *
   * @param when when it was graded, as shown (e.g. "2026-03-05 14:02 UTC")
   * @param version the JAria version that graded it
   * @param timeout the time allowed per student
   * @param jobs how many students were graded at once
   */
  public record RunInfo(String when, String version, Duration timeout, int jobs) {}

  private final Assignment assignment;
  private final List<Grader.Result> results;
  private final String lang;
  private final boolean unsafe;
  private final RunInfo run;

  /** The report of {@code results} for {@code assignment}, in English, graded in isolation. */
  public GradeReport(Assignment assignment, List<Grader.Result> results) {
    this(assignment, results, "en", false, null);
  }

  /**
   * The report of {@code results} for {@code assignment} in {@code lang}; {@code unsafe} if the
   * submissions ran without isolation (every report then says so); {@code run} for the heading (or
   * null for none).
   */
  public GradeReport(
      Assignment assignment,
      List<Grader.Result> results,
      String lang,
      boolean unsafe,
      RunInfo run) {
    this.assignment = assignment;
    this.results = List.copyOf(results);
    this.lang = lang;
    this.unsafe = unsafe;
    this.run = run;
  }

  /** The results. */
  public List<Grader.Result> results() {
    return results;
  }

  private boolean es() {
    return "es".equals(lang);
  }

  private String w(String en, String es) {
    return es() ? es : en;
  }

  /** The warning every report of an unsafe grading carries. */
  public static final String UNSAFE_WARNING =
      "WARNING: graded with --unsafe: the submissions ran without isolation and could have read or"
          + " changed anything the grader's user can, grades included. Do not trust these grades.";

  private String warning() {
    return unsafe ? UNSAFE_WARNING + "\n\n" : "";
  }

  private String title() {
    return w("Assignment ", "Práctica ") + assignment.id() + ": " + assignment.title();
  }

  /** "Graded 2026-03-05 14:02 UTC by JAria 0.1.0: timeout 10 s per student, 2 jobs", or "". */
  private String heading() {
    if (run == null) {
      return "";
    }
    return String.format(
        Locale.ROOT,
        w(
            "Graded %s by JAria %s: assignment %s, timeout %d s per student, %d %s",
            "Evaluado el %s con JAria %s: práctica %s, límite %d s por estudiante, %d %s"),
        run.when(),
        run.version(),
        assignment.id(),
        run.timeout().toSeconds(),
        run.jobs(),
        run.jobs() == 1 ? w("job", "tarea") : w("jobs", "tareas"));
  }

  private static String score(Grader.Result r) {
    return r.grade().score() + "/" + r.grade().maxScore();
  }

  /** The first problem, whole: its check's name and message, on one line. */
  private static String firstProblem(Grader.Result r) {
    List<Check> f = r.grade().failures();
    if (f.isEmpty()) {
      return "-";
    }
    return Neutral.line(f.get(0).name() + ": " + f.get(0).message());
  }

  /** The class statistics. */
  public ClassStats stats() {
    return ClassStats.of(results, assignment.points());
  }

  private String statsText() {
    ClassStats s = stats();
    StringBuilder sb = new StringBuilder();
    String students =
        s.students() == 1
            ? w("1 student", "1 estudiante")
            : s.students() + w(" students", " estudiantes");
    sb.append(
        String.format(
            Locale.ROOT,
            w("%s, mean %.1f/%d, median %.1f%n", "%s, media %.1f/%d, mediana %.1f%n"),
            students,
            s.mean(),
            s.maxScore(),
            s.median()));
    sb.append(w("Scores: ", "Notas: "));
    List<String> parts = new ArrayList<>();
    s.byScore().forEach((k, v) -> parts.add(k + ":" + v));
    sb.append(String.join("  ", parts)).append('\n');
    sb.append(w("Statuses: ", "Estados: "));
    parts.clear();
    s.byStatus().forEach((k, v) -> parts.add(k + ":" + v));
    sb.append(String.join("  ", parts)).append('\n');
    sb.append(w("Most failed checks:\n", "Comprobaciones más falladas:\n"));
    s.mostFailed().forEach((k, v) -> sb.append("  ").append(v).append("  ").append(k).append('\n'));
    return sb.toString();
  }

  /** A plain-text table, the class statistics and every student's checks. */
  public String text() {
    int w =
        Math.max(
            8, results.stream().mapToInt(r -> Neutral.line(r.student()).length()).max().orElse(8));
    StringBuilder sb = new StringBuilder(warning()).append(title()).append('\n');
    if (run != null) {
      sb.append(heading()).append('\n');
    }
    sb.append('\n');
    String row = "%-" + w + "s  %7s  %-16s  %s%n";
    sb.append(
        String.format(
            Locale.ROOT,
            row,
            w("student", "estudiante"),
            w("score", "nota"),
            w("status", "estado"),
            w("first problem", "primer problema")));
    for (Grader.Result r : results) {
      sb.append(
          String.format(
              Locale.ROOT, row, Neutral.line(r.student()), score(r), r.status(), firstProblem(r)));
    }
    sb.append('\n').append(statsText());
    for (Grader.Result r : results) {
      sb.append("\n").append(Neutral.line(r.student())).append(" (").append(score(r)).append(")\n");
      for (Check c : r.grade().checks()) {
        sb.append(c.passed() ? "  [PASS] " : "  [FAIL] ")
            .append(c.name())
            .append(" (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): ")
            .append(Neutral.text(c.message()).replace("\n", "\n      "))
            .append('\n');
      }
      for (String n : r.grade().notes()) {
        sb.append(w("  Note: ", "  Nota: ")).append(Neutral.line(n)).append('\n');
      }
    }
    return sb.toString();
  }

  /** A Markdown table, the class statistics and every student's checks. */
  public String markdown() {
    StringBuilder sb = new StringBuilder();
    if (unsafe) {
      sb.append("> **").append(UNSAFE_WARNING).append("**\n\n");
    }
    sb.append("# ").append(Neutral.markdown(title())).append("\n\n");
    if (run != null) {
      sb.append(Neutral.markdown(heading())).append("\n\n");
    }
    sb.append(
        w(
            "| Student | Score | Status | First problem |\n|---|---|---|---|\n",
            "| Estudiante | Nota | Estado | Primer problema |\n|---|---|---|---|\n"));
    for (Grader.Result r : results) {
      sb.append("| ")
          .append(Neutral.markdown(Neutral.line(r.student())))
          .append(" | ")
          .append(score(r))
          .append(" | ")
          .append(r.status())
          .append(" | ")
          .append(Neutral.markdown(firstProblem(r)))
          .append(" |\n");
    }
    sb.append("\n```\n").append(Neutral.text(statsText()).replace("```", "'''")).append("```\n");
    for (Grader.Result r : results) {
      sb.append("\n## ")
          .append(Neutral.markdown(Neutral.line(r.student())))
          .append(" — ")
          .append(score(r))
          .append("\n\n");
      for (Check c : r.grade().checks()) {
        sb.append("- ")
            .append(c.passed() ? "✅ " : "❌ ")
            .append("**")
            .append(Neutral.markdown(c.name()))
            .append("** (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): ")
            .append(Neutral.markdown(c.message()).replace("\n", "<br>"))
            .append('\n');
      }
      for (String n : r.grade().notes()) {
        sb.append("- ").append(w("Note: ", "Nota: ")).append(Neutral.markdown(n)).append('\n');
      }
    }
    return sb.toString();
  }

  /** A standalone HTML page with the table, the statistics and every student's checks. */
  public String html() {
    StringBuilder sb = new StringBuilder();
    sb.append("<!DOCTYPE html>\n<html lang=\"")
        .append(es() ? "es" : "en")
        .append("\"><head><meta charset=\"utf-8\"><title>")
        .append(Neutral.html(title()))
        .append("</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:2em auto}")
        .append("table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;")
        .append("text-align:left;vertical-align:top}.pass{color:#060}.fail{color:#a00}")
        .append(".warn{background:#fdd;padding:1em;font-weight:bold}")
        .append("pre{white-space:pre-wrap;margin:0}</style></head><body>\n");
    if (unsafe) {
      sb.append("<p class=\"warn\">").append(Neutral.html(UNSAFE_WARNING)).append("</p>\n");
    }
    sb.append("<h1>").append(Neutral.html(title())).append("</h1>\n");
    if (run != null) {
      sb.append("<p>").append(Neutral.html(heading())).append("</p>\n");
    }
    sb.append("<table>\n<tr><th>")
        .append(w("Student", "Estudiante"))
        .append("</th><th>")
        .append(w("Score", "Nota"))
        .append("</th><th>")
        .append(w("Status", "Estado"))
        .append("</th><th>")
        .append(w("First problem", "Primer problema"))
        .append("</th></tr>\n");
    for (int i = 0; i < results.size(); i++) {
      Grader.Result r = results.get(i);
      sb.append("<tr><td><a href=\"#s")
          .append(i + 1)
          .append("\">")
          .append(Neutral.html(Neutral.line(r.student())))
          .append("</a></td><td>")
          .append(score(r))
          .append("</td><td>")
          .append(r.status())
          .append("</td><td>")
          .append(Neutral.html(firstProblem(r)))
          .append("</td></tr>\n");
    }
    sb.append("</table>\n<pre>").append(Neutral.html(statsText())).append("</pre>\n");
    for (int i = 0; i < results.size(); i++) {
      Grader.Result r = results.get(i);
      sb.append("<h2 id=\"s")
          .append(i + 1)
          .append("\">")
          .append(Neutral.html(Neutral.line(r.student())))
          .append(" — ")
          .append(score(r))
          .append("</h2>\n<ul>\n");
      for (Check c : r.grade().checks()) {
        sb.append("<li class=\"")
            .append(c.passed() ? "pass" : "fail")
            .append("\"><b>")
            .append(c.passed() ? "PASS" : "FAIL")
            .append(" ")
            .append(Neutral.html(c.name()))
            .append("</b> (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): <pre>")
            .append(Neutral.html(c.message()))
            .append("</pre></li>\n");
      }
      for (String n : r.grade().notes()) {
        sb.append("<li>").append(w("Note: ", "Nota: ")).append(Neutral.html(n)).append("</li>\n");
      }
      sb.append("</ul>\n");
    }
    return sb.append("</body></html>\n").toString();
  }

  /**
   * The gradebook as CSV: student, score, max, status, then one column per check of the assignment
   * (the points earned; empty where that check was not made, e.g. for a submission that did not
   * compile). The columns are the assignment's, in the report's language, whatever the language
   * each student was graded in and whoever ran.
   */
  public String csv() {
    List<String> columns = assignment.checkNames(assignment.texts(lang));
    Map<String, Integer> column = new HashMap<>();
    for (String l : Texts.LANGUAGES.stream().sorted().toList()) {
      List<String> names = assignment.checkNames(assignment.texts(l));
      for (int i = 0; i < names.size() && i < columns.size(); i++) {
        column.putIfAbsent(names.get(i), i);
      }
    }
    StringBuilder sb = new StringBuilder("student,score,max,status");
    for (String c : columns) {
      sb.append(',').append(Neutral.csv(c));
    }
    sb.append('\n');
    for (Grader.Result r : results) {
      sb.append(Neutral.csv(r.student()))
          .append(',')
          .append(r.grade().score())
          .append(',')
          .append(r.grade().maxScore())
          .append(',')
          .append(r.status());
      int[] earned = new int[columns.size()];
      Arrays.fill(earned, -1);
      for (Check c : r.grade().checks()) {
        Integer i = column.get(c.name());
        if (i != null) {
          earned[i] = Math.max(0, earned[i]) + c.earned();
        }
      }
      for (int e : earned) {
        sb.append(',');
        if (e >= 0) {
          sb.append(e);
        }
      }
      sb.append('\n');
    }
    return sb.toString();
  }

  /** The feedback to hand back to one student: their score, what happened, every check. */
  public String feedback(Grader.Result r) {
    StringBuilder sb = new StringBuilder(warning());
    sb.append(title()).append('\n');
    sb.append(w("Student: ", "Estudiante: ")).append(Neutral.line(r.student())).append('\n');
    sb.append(w("Score: ", "Nota: ")).append(score(r)).append('\n');
    sb.append(w("Status: ", "Estado: "))
        .append(r.status())
        .append(" — ")
        .append(r.status().sentence(lang))
        .append("\n\n");
    for (Check c : r.grade().checks()) {
      sb.append(c.passed() ? w("[PASS] ", "[BIEN] ") : w("[FAIL] ", "[MAL]  "))
          .append(c.name())
          .append(" (")
          .append(c.earned())
          .append('/')
          .append(c.points())
          .append(")\n       ")
          .append(Neutral.text(c.message()).replace("\n", "\n       "))
          .append('\n');
    }
    for (String n : r.grade().notes()) {
      sb.append('\n').append(w("Note: ", "Nota: ")).append(Neutral.line(n)).append('\n');
    }
    return sb.toString();
  }
}
