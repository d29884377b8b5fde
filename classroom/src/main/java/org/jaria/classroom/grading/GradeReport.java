package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * A grading run as a teacher reads it: a plain-text table, Markdown, an HTML page, a CSV gradebook
 * and one feedback text per student, in English or Spanish ({@code lang} "en" or "es"; the checks'
 * own messages are in English).
 */
public final class GradeReport {

  private final Assignment assignment;
  private final List<Grader.Result> results;
  private final String lang;
  private final boolean unsafe;

  /** The report of {@code results} for {@code assignment}, in English, graded in isolation. */
  public GradeReport(Assignment assignment, List<Grader.Result> results) {
    this(assignment, results, "en", false);
  }

  /**
   * The report of {@code results} for {@code assignment} in {@code lang}; {@code unsafe} if the
   * submissions ran without isolation (every report then says so).
   */
  public GradeReport(
      Assignment assignment, List<Grader.Result> results, String lang, boolean unsafe) {
    this.assignment = assignment;
    this.results = List.copyOf(results);
    this.lang = lang;
    this.unsafe = unsafe;
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

  private static String score(Grader.Result r) {
    return r.grade().score() + "/" + r.grade().maxScore();
  }

  private static String firstProblem(Grader.Result r) {
    List<Check> f = r.grade().failures();
    if (f.isEmpty()) {
      return "-";
    }
    String m = f.get(0).name() + ": " + f.get(0).message().replace('\n', ' ');
    return m.length() > 110 ? m.substring(0, 107) + "..." : m;
  }

  /** The class statistics. */
  public ClassStats stats() {
    return ClassStats.of(results, assignment.points());
  }

  private String statsText() {
    ClassStats s = stats();
    StringBuilder sb = new StringBuilder();
    sb.append(
        String.format(
            Locale.ROOT,
            w(
                "%d students, mean %.1f/%d, median %.1f%n",
                "%d estudiantes, media %.1f/%d, mediana %.1f%n"),
            s.students(),
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
    int w = Math.max(8, results.stream().mapToInt(r -> r.student().length()).max().orElse(8));
    StringBuilder sb = new StringBuilder(warning()).append(title()).append("\n\n");
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
          String.format(Locale.ROOT, row, r.student(), score(r), r.status(), firstProblem(r)));
    }
    sb.append('\n').append(statsText());
    for (Grader.Result r : results) {
      sb.append("\n").append(r.student()).append(" (").append(score(r)).append(")\n");
      for (Check c : r.grade().checks()) {
        sb.append(c.passed() ? "  [PASS] " : "  [FAIL] ")
            .append(c.name())
            .append(" (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): ")
            .append(c.message().replace("\n", "\n      "))
            .append('\n');
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
    sb.append("# ").append(title()).append("\n\n");
    sb.append(
        w(
            "| Student | Score | Status | First problem |\n|---|---|---|---|\n",
            "| Estudiante | Nota | Estado | Primer problema |\n|---|---|---|---|\n"));
    for (Grader.Result r : results) {
      sb.append("| ")
          .append(mdCell(r.student()))
          .append(" | ")
          .append(score(r))
          .append(" | ")
          .append(r.status())
          .append(" | ")
          .append(mdCell(firstProblem(r)))
          .append(" |\n");
    }
    sb.append("\n```\n").append(statsText()).append("```\n");
    for (Grader.Result r : results) {
      sb.append("\n## ").append(mdCell(r.student())).append(" — ").append(score(r)).append("\n\n");
      for (Check c : r.grade().checks()) {
        sb.append("- ")
            .append(c.passed() ? "✅ " : "❌ ")
            .append("**")
            .append(mdCell(c.name()))
            .append("** (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): ")
            .append(mdCell(c.message()).replace("\n", "<br>"))
            .append('\n');
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
        .append(esc(title()))
        .append("</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:2em auto}")
        .append("table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;")
        .append("text-align:left;vertical-align:top}.pass{color:#060}.fail{color:#a00}")
        .append(".warn{background:#fdd;padding:1em;font-weight:bold}")
        .append("pre{white-space:pre-wrap;margin:0}</style></head><body>\n");
    if (unsafe) {
      sb.append("<p class=\"warn\">").append(esc(UNSAFE_WARNING)).append("</p>\n");
    }
    sb.append("<h1>")
        .append(esc(title()))
        .append("</h1>\n<table>\n<tr><th>")
        .append(w("Student", "Estudiante"))
        .append("</th><th>")
        .append(w("Score", "Nota"))
        .append("</th><th>")
        .append(w("Status", "Estado"))
        .append("</th><th>")
        .append(w("First problem", "Primer problema"))
        .append("</th></tr>\n");
    for (Grader.Result r : results) {
      sb.append("<tr><td><a href=\"#")
          .append(anchor(r.student()))
          .append("\">")
          .append(esc(r.student()))
          .append("</a></td><td>")
          .append(score(r))
          .append("</td><td>")
          .append(r.status())
          .append("</td><td>")
          .append(esc(firstProblem(r)))
          .append("</td></tr>\n");
    }
    sb.append("</table>\n<pre>").append(esc(statsText())).append("</pre>\n");
    for (Grader.Result r : results) {
      sb.append("<h2 id=\"")
          .append(anchor(r.student()))
          .append("\">")
          .append(esc(r.student()))
          .append(" — ")
          .append(score(r))
          .append("</h2>\n<ul>\n");
      for (Check c : r.grade().checks()) {
        sb.append("<li class=\"")
            .append(c.passed() ? "pass" : "fail")
            .append("\"><b>")
            .append(c.passed() ? "PASS" : "FAIL")
            .append(" ")
            .append(esc(c.name()))
            .append("</b> (")
            .append(c.earned())
            .append('/')
            .append(c.points())
            .append("): <pre>")
            .append(esc(c.message()))
            .append("</pre></li>\n");
      }
      sb.append("</ul>\n");
    }
    return sb.append("</body></html>\n").toString();
  }

  /**
   * The gradebook as CSV: student, score, max, status, then one column per check (the points
   * earned; empty where that check was not made, e.g. for a submission that did not compile).
   */
  public String csv() {
    Set<String> checks = new LinkedHashSet<>();
    for (Grader.Result r : results) {
      if (r.status() == Status.GRADED) {
        r.grade().checks().forEach(c -> checks.add(c.name()));
      }
    }
    StringBuilder sb = new StringBuilder("student,score,max,status");
    for (String c : checks) {
      sb.append(',').append(csvCell(c));
    }
    sb.append('\n');
    for (Grader.Result r : results) {
      sb.append(csvCell(r.student()))
          .append(',')
          .append(r.grade().score())
          .append(',')
          .append(r.grade().maxScore())
          .append(',')
          .append(r.status());
      Map<String, Integer> earned = new java.util.HashMap<>();
      r.grade().checks().forEach(c -> earned.merge(c.name(), c.earned(), Integer::sum));
      for (String c : checks) {
        sb.append(',');
        Integer e = earned.get(c);
        if (e != null) {
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
    sb.append(w("Student: ", "Estudiante: ")).append(r.student()).append('\n');
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
          .append(c.message().replace("\n", "\n       "))
          .append('\n');
    }
    return sb.toString();
  }

  private static String csvCell(String text) {
    // a cell a spreadsheet would run as a formula is quoted as text
    String s = text.matches("^[=+\\-@].*") ? "'" + text : text;
    if (s.contains(",") || s.contains("\"") || s.contains("\n")) {
      return "\"" + s.replace("\"", "\"\"") + "\"";
    }
    return s;
  }

  private static String mdCell(String s) {
    return s.replace("|", "\\|");
  }

  private static String anchor(String s) {
    return "s-" + s.replaceAll("[^A-Za-z0-9_-]", "_");
  }

  static String esc(String s) {
    return s.replace("&", "&amp;")
        .replace("<", "&lt;")
        .replace(">", "&gt;")
        .replace("\"", "&quot;");
  }
}
