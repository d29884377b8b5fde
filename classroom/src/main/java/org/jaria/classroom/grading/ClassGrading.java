package org.jaria.classroom.grading;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.classroom.sandbox.Sandbox;

/**
 * A teacher's whole grading run ({@code jaria grade}): checks the {@link GradeRequest}, chooses the
 * sandbox, grades every submission with a {@link Grader} while printing progress, and writes
 * report.txt, report.md, report.html, gradebook.csv and students/NAME/feedback.txt. A request that
 * cannot be carried out is refused with a line on the error stream that says what to change, and
 * nothing is graded.
 */
public final class ClassGrading {

  /** The run finished and the reports are written. */
  public static final int GRADED = 0;

  /** The request was refused (the error stream says why); nothing was graded. */
  public static final int REFUSED = 2;

  private ClassGrading() {}

  /**
   * Carries out {@code r}, printing progress and the class's report on {@code o} and problems on
   * {@code err}.
   *
   * @return {@link #GRADED} or {@link #REFUSED}
   * @throws IOException if a report cannot be written
   */
  public static int grade(GradeRequest r, PrintWriter o, PrintWriter err) throws IOException {
    if (r.timeout().isNegative() || r.timeout().isZero() || r.jobs() <= 0) {
      err.println("grade: --timeout and --jobs must be positive");
      return REFUSED;
    }
    if (!Texts.LANGUAGES.contains(r.lang())) {
      err.println("grade: --lang is en or es");
      return REFUSED;
    }
    Assignment a;
    List<Path> found;
    try {
      a = Assignments.byId(r.assignment());
      found = SubmissionFolders.submissions(r.submissions());
    } catch (IllegalArgumentException | IOException e) {
      err.println("grade: " + e.getMessage());
      return REFUSED;
    }
    if (found.isEmpty()) {
      err.println(
          "grade: no submissions in "
              + r.submissions()
              + ": put each student's .java files in a folder of their own inside it");
      return REFUSED;
    }
    Path subsReal = r.submissions().toAbsolutePath().normalize();
    Path outAbs = r.out().toAbsolutePath().normalize();
    if (outAbs.startsWith(subsReal)) {
      err.println("grade: put --out outside the submissions folder (students must not see it)");
      return REFUSED;
    }
    Sandbox sandbox;
    if (r.unsafe()) {
      sandbox = Sandbox.none();
      err.println(GradeReport.UNSAFE_WARNING);
    } else {
      try {
        sandbox = Sandbox.bubblewrap(r.bwrap());
      } catch (IllegalStateException e) {
        err.println(
            "grade: cannot isolate the submissions: "
                + e.getMessage()
                + ". Refusing to grade; --unsafe grades anyway (only for code you trust).");
        return REFUSED;
      }
    }
    List<Path> toGrade = found;
    if (r.only() != null) {
      toGrade =
          found.stream().filter(p -> SubmissionFolders.studentOf(p).equals(r.only())).toList();
      if (toGrade.isEmpty()) {
        err.println("grade: no submission called '" + r.only() + "' in " + r.submissions());
        return REFUSED;
      }
    }
    Path students = r.out().resolve("students");
    Grader grader =
        new Grader(
            a, Grader.Options.of(r.timeout(), r.jobs(), sandbox).in(Texts.of(r.lang())), students);
    o.printf(
        Locale.ROOT,
        "Grading %d submission(s) of '%s', %d at a time%s...%n",
        toGrade.size(),
        a.id(),
        Math.min(r.jobs(), toGrade.size()),
        sandbox.isolated() ? ", each in a sandbox" : ", WITHOUT isolation (--unsafe)");
    o.flush();
    AtomicInteger done = new AtomicInteger();
    int total = toGrade.size();
    List<Grader.Result> graded =
        grader.gradeAll(
            toGrade,
            g -> {
              o.printf(
                  Locale.ROOT,
                  "  [%d/%d] %-20s %3d/%d  %s (%.1f s)%n",
                  done.incrementAndGet(),
                  total,
                  g.student(),
                  g.grade().score(),
                  g.grade().maxScore(),
                  g.status(),
                  g.seconds());
              o.flush();
            });
    List<Grader.Result> results = new ArrayList<>();
    if (r.only() == null) {
      results.addAll(graded);
    } else {
      // the others as graded before, from their files in the report
      for (Path p : found) {
        String name = SubmissionFolders.studentOf(p);
        if (name.equals(r.only())) {
          results.add(graded.get(0));
          continue;
        }
        try {
          results.add(ResultFiles.read(students.resolve(SubmissionFolders.safeName(name)), name));
        } catch (IOException e) {
          err.println(
              "grade: "
                  + name
                  + " has no earlier result in "
                  + r.out()
                  + " (grade the class first)");
        }
      }
    }
    writeReports(new GradeReport(a, results, r.lang(), r.unsafe()), r.out(), students, o);
    return GRADED;
  }

  private static void writeReports(GradeReport report, Path out, Path students, PrintWriter o)
      throws IOException {
    Files.createDirectories(out);
    Files.writeString(out.resolve("report.txt"), report.text(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.md"), report.markdown(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.html"), report.html(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("gradebook.csv"), report.csv(), StandardCharsets.UTF_8);
    for (Grader.Result r : report.results()) {
      Path dir = students.resolve(SubmissionFolders.safeName(r.student()));
      Files.createDirectories(dir);
      Files.writeString(dir.resolve("feedback.txt"), report.feedback(r), StandardCharsets.UTF_8);
    }
    o.println();
    o.print(report.text());
    o.println();
    o.println(
        "Reports written to "
            + out.toAbsolutePath().normalize()
            + " (report.md, .html, .txt, gradebook.csv, students/NAME/feedback.txt)");
    o.flush();
  }
}
