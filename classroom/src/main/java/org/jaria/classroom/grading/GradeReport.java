package org.jaria.classroom.grading;

import java.util.List;
import java.util.Locale;

/** A grading run as a teacher reads it: a plain-text table, Markdown, or an HTML page. */
public final class GradeReport {

  private final Assignment assignment;
  private final List<Grader.Result> results;

  /** The report of {@code results} for {@code assignment}. */
  public GradeReport(Assignment assignment, List<Grader.Result> results) {
    this.assignment = assignment;
    this.results = List.copyOf(results);
  }

  /** The results. */
  public List<Grader.Result> results() {
    return results;
  }

  private String title() {
    return "Assignment " + assignment.id() + ": " + assignment.title();
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

  /** A plain-text table and every student's checks. */
  public String text() {
    int w = Math.max(8, results.stream().mapToInt(r -> r.student().length()).max().orElse(8));
    StringBuilder sb = new StringBuilder(title()).append("\n\n");
    String row = "%-" + w + "s  %7s  %-13s  %s%n";
    sb.append(String.format(Locale.ROOT, row, "student", "score", "status", "first problem"));
    for (Grader.Result r : results) {
      sb.append(
          String.format(Locale.ROOT, row, r.student(), score(r), r.status(), firstProblem(r)));
    }
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

  /** A Markdown table and every student's checks. */
  public String markdown() {
    StringBuilder sb = new StringBuilder("# ").append(title()).append("\n\n");
    sb.append("| Student | Score | Status | First problem |\n|---|---|---|---|\n");
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

  /** A standalone HTML page with the table and every student's checks. */
  public String html() {
    StringBuilder sb = new StringBuilder();
    sb.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>")
        .append(esc(title()))
        .append("</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:2em auto}")
        .append("table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;")
        .append("text-align:left;vertical-align:top}.pass{color:#060}.fail{color:#a00}")
        .append("pre{white-space:pre-wrap;margin:0}</style></head><body>\n<h1>")
        .append(esc(title()))
        .append("</h1>\n<table>\n<tr><th>Student</th><th>Score</th><th>Status</th>")
        .append("<th>First problem</th></tr>\n");
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
    sb.append("</table>\n");
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
