package org.jaria.classroom.classgrading;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.GradeReport;
import org.jaria.classroom.grading.Grader;
import org.jaria.classroom.grading.Neutral;
import org.jaria.classroom.grading.ResultFiles;
import org.jaria.classroom.grading.SubmissionFolders;
import org.jaria.classroom.grading.Texts;
import org.jaria.classroom.pack.Packs;
import org.jaria.classroom.platform.Platform;
import org.jaria.classroom.platform.Platforms;
import org.jaria.classroom.sandbox.Sandbox;

/**
 * A teacher's whole grading run ({@code jaria grade}): checks the {@link GradeRequest}, loads the
 * assignment packs, chooses the sandbox, grades every submission with a {@link Grader} while
 * printing progress, and writes report.txt, report.md, report.html, gradebook.csv and
 * students/NAME/feedback.txt (and, for Gradescope or GitHub Classroom, what those read). A request
 * that cannot be carried out is refused with a line on the error stream that says what to change,
 * and nothing is graded.
 */
public final class ClassGrading {

  /** The run finished and the reports are written. */
  public static final int GRADED = 0;

  /** The request was refused (the error stream says why); nothing was graded. */
  public static final int REFUSED = 2;

  private static final DateTimeFormatter WHEN =
      DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'", Locale.ROOT).withZone(ZoneOffset.UTC);

  private ClassGrading() {}

  /** The JAria version of this classroom library, as its build wrote it. */
  public static String version() {
    Properties p = new Properties();
    try (InputStream in =
        ClassGrading.class.getResourceAsStream("/org/jaria/classroom/version.properties")) {
      if (in != null) {
        p.load(in);
      }
    } catch (IOException e) {
      // unknown
    }
    String v = p.getProperty("version", "unknown");
    return v.startsWith("$") ? "unknown" : v;
  }

  /**
   * Carries out {@code r}, printing progress and the class's report on {@code o} and problems on
   * {@code err}.
   *
   * @return {@link #GRADED} or {@link #REFUSED}
   * @throws IOException if a report cannot be written
   */
  public static int grade(GradeRequest r, PrintWriter o, PrintWriter err) throws IOException {
    String refused = refusal(r);
    if (refused != null) {
      return refuse(r, refused, o, err);
    }
    try (Packs packs = Packs.load(r.packs(), r.scratchRoot())) {
      return grade(r, packs, o, err);
    } catch (IllegalArgumentException | IllegalStateException e) {
      return refuse(r, e.getMessage(), o, err);
    }
  }

  /** Why {@code r} cannot be carried out whatever the packs, or null. */
  private static String refusal(GradeRequest r) {
    if (r.timeout().isNegative() || r.timeout().isZero() || r.jobs() <= 0) {
      return "--timeout and --jobs must be positive";
    }
    if (!Texts.LANGUAGES.contains(r.lang())) {
      return "--lang is en or es";
    }
    if (r.platform() != Platform.LOCAL && r.only() != null) {
      return "--only re-grades one student of a class; Gradescope and GitHub Classroom grade one"
          + " submission at a time";
    }
    return null;
  }

  private static int refuse(GradeRequest r, String why, PrintWriter o, PrintWriter err)
      throws IOException {
    err.println("grade: " + why);
    err.flush();
    Platforms.refused(r.platform(), r.platformOut(), r.lang(), why, o);
    return REFUSED;
  }

  private static int grade(GradeRequest r, Packs packs, PrintWriter o, PrintWriter err)
      throws IOException {
    Assignment a;
    SubmissionFolders.Scan scan;
    try {
      a = packs.byId(r.assignment());
      scan =
          r.platform() == Platform.LOCAL
              ? SubmissionFolders.scan(r.submissions())
              : SubmissionFolders.single(r.submissions());
    } catch (IllegalArgumentException | IOException e) {
      return refuse(r, e.getMessage(), o, err);
    }
    if (scan.submissions().isEmpty()) {
      return refuse(
          r,
          "no submissions in "
              + r.submissions()
              + ": put each student's .java files in a folder of their own inside it",
          o,
          err);
    }
    Path subsReal = r.submissions().toAbsolutePath().normalize();
    Path outAbs = r.out().toAbsolutePath().normalize();
    if (outAbs.startsWith(subsReal)) {
      return refuse(
          r, "put --out outside the submissions folder (students must not see it)", o, err);
    }
    Sandbox sandbox;
    if (r.unsafe()) {
      sandbox = Sandbox.none();
      err.println(GradeReport.UNSAFE_WARNING);
    } else {
      try {
        sandbox = Sandbox.bubblewrap(r.bwrap());
      } catch (IllegalStateException e) {
        return refuse(
            r,
            "cannot isolate the submissions: "
                + e.getMessage()
                + ". Refusing to grade; --unsafe grades anyway (only for code you trust).",
            o,
            err);
      }
    }
    for (String s : scan.skipped()) {
      err.println("grade: warning: " + Neutral.line(s));
    }
    List<String> names =
        scan.submissions().stream().map(SubmissionFolders.Submission::student).toList();
    Map<String, String> folders = SubmissionFolders.reportFolders(names);
    List<SubmissionFolders.Submission> toGrade = scan.submissions();
    if (r.only() != null) {
      toGrade = toGrade.stream().filter(s -> s.student().equals(r.only())).toList();
      if (toGrade.isEmpty()) {
        return refuse(r, "no submission called '" + r.only() + "' in " + r.submissions(), o, err);
      }
    }
    Texts texts = a.texts(r.lang());
    Path students = r.out().resolve("students");
    Grader grader =
        new Grader(
            a,
            Grader.Options.of(r.timeout(), r.jobs(), sandbox).in(texts).scratchIn(r.scratchRoot()),
            students);
    // on a platform, standard output is the student's feedback alone: progress goes to errors
    PrintWriter progress = r.platform() == Platform.LOCAL ? o : err;
    progress.printf(
        Locale.ROOT,
        "Grading %d submission(s) of '%s', %d at a time%s...%n",
        toGrade.size(),
        a.id(),
        Math.min(r.jobs(), toGrade.size()),
        sandbox.isolated() ? ", each in a sandbox" : ", WITHOUT isolation (--unsafe)");
    progress.flush();
    AtomicInteger done = new AtomicInteger();
    int total = toGrade.size();
    List<Grader.Result> graded =
        grader.gradeAll(
            toGrade,
            folders,
            g -> {
              progress.printf(
                  Locale.ROOT,
                  "  [%d/%d] %-20s %3d/%d  %s (%.1f s)%n",
                  done.incrementAndGet(),
                  total,
                  Neutral.line(g.student()),
                  g.grade().score(),
                  g.grade().maxScore(),
                  g.status(),
                  g.seconds());
              progress.flush();
            });
    List<Grader.Result> results = new ArrayList<>();
    if (r.only() == null) {
      results.addAll(graded);
    } else {
      // the others as graded before, from their files in the report
      for (String name : names) {
        if (name.equals(r.only())) {
          results.add(graded.get(0));
          continue;
        }
        try {
          results.add(ResultFiles.read(students.resolve(folders.get(name)), name));
        } catch (IOException e) {
          err.println(
              "grade: "
                  + Neutral.line(name)
                  + " has no earlier result in "
                  + r.out()
                  + " (grade the class first): "
                  + Neutral.line(String.valueOf(e.getMessage())));
        }
      }
    }
    GradeReport report =
        new GradeReport(
            a,
            results,
            r.lang(),
            r.unsafe(),
            new GradeReport.RunInfo(
                WHEN.format(r.clock().instant()), r.version(), r.timeout(), r.jobs()));
    writeReports(report, r.out(), students, folders, o, r.platform() == Platform.LOCAL);
    Platforms.graded(r.platform(), r.platformOut(), report, results.get(0), o);
    return GRADED;
  }

  private static void writeReports(
      GradeReport report,
      Path out,
      Path students,
      Map<String, String> folders,
      PrintWriter o,
      boolean printReport)
      throws IOException {
    Files.createDirectories(out);
    Files.writeString(out.resolve("report.txt"), report.text(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.md"), report.markdown(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.html"), report.html(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("gradebook.csv"), report.csv(), StandardCharsets.UTF_8);
    for (Grader.Result r : report.results()) {
      Path dir = students.resolve(folders.get(r.student()));
      Files.createDirectories(dir);
      Files.writeString(dir.resolve("feedback.txt"), report.feedback(r), StandardCharsets.UTF_8);
    }
    if (printReport) {
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
}
