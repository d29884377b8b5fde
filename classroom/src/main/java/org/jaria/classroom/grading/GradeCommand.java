package org.jaria.classroom.grading;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.classroom.sandbox.Sandbox;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code jaria grade}: grades a folder of student submissions on the simulator. */
@Command(
    name = "grade",
    mixinStandardHelpOptions = true,
    description = {
      "Grade students' solutions of a classroom assignment on the simulator, in lockstep time.",
      "SUBMISSIONS holds one folder per student with their .java files (or is itself one"
          + " submission). Each is copied and compiled here, then runs in a JVM of its own inside"
          + " a bubblewrap sandbox (no network, no other files, limits on time, memory and"
          + " threads) while the simulator and the grade stay in this process. Writes report.txt,"
          + " report.md, report.html, gradebook.csv and students/NAME/feedback.txt."
    })
public final class GradeCommand implements Callable<Integer> {

  @Option(
      names = {"-a", "--assignment"},
      paramLabel = "ID",
      description = "The assignment: square, wall, goals or ball.")
  String assignment;

  @Option(
      names = {"-o", "--out"},
      paramLabel = "DIR",
      description = "Where the reports and each student's files go (default: ${DEFAULT-VALUE}).",
      defaultValue = "grading-report")
  Path out;

  @Option(
      names = "--timeout",
      paramLabel = "SECONDS",
      description = "Real time allowed per student (default: ${DEFAULT-VALUE}).",
      defaultValue = "60")
  long timeoutSeconds;

  @Option(
      names = {"-j", "--jobs"},
      paramLabel = "N",
      description =
          "Students graded at once (default: ${DEFAULT-VALUE}); results are the same for any N.",
      defaultValue = "1")
  int jobs;

  @Option(
      names = "--only",
      paramLabel = "STUDENT",
      description =
          "Re-grade only this student (a folder in SUBMISSIONS) into the existing report in --out.")
  String only;

  @Option(
      names = "--lang",
      paramLabel = "LANG",
      description = "Language of the reports and feedback: en or es (default: ${DEFAULT-VALUE}).",
      defaultValue = "en")
  String lang;

  @Option(
      names = "--unsafe",
      description =
          "Grade even where no isolation is available: submissions then run as your user and"
              + " could change anything you can, grades included. Every report says so.")
  boolean unsafe;

  @Option(
      names = "--bwrap",
      paramLabel = "PROGRAM",
      description =
          "The bubblewrap program that isolates the submissions (default: ${DEFAULT-VALUE}).",
      defaultValue = "/usr/bin/bwrap")
  Path bwrap;

  @Option(names = "--list", description = "List the assignments and exit.")
  boolean list;

  @Parameters(paramLabel = "SUBMISSIONS", arity = "0..1", description = "The submissions folder.")
  Path submissions;

  @CommandLine.Spec CommandLine.Model.CommandSpec spec;

  @Override
  public Integer call() throws IOException {
    PrintWriter o = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if (list) {
      for (Assignment a : Assignments.all()) {
        o.printf(Locale.ROOT, "%-7s %s (%d points)%n", a.id(), a.title(), a.points());
      }
      o.flush();
      return 0;
    }
    if (assignment == null || submissions == null) {
      err.println("grade: give --assignment ID and a SUBMISSIONS folder (--list shows the ids)");
      return 2;
    }
    if (timeoutSeconds <= 0 || jobs <= 0) {
      err.println("grade: --timeout and --jobs must be positive");
      return 2;
    }
    if (!lang.equals("en") && !lang.equals("es")) {
      err.println("grade: --lang is en or es");
      return 2;
    }
    Assignment a;
    List<Path> found;
    try {
      a = Assignments.byId(assignment);
      found = SubmissionFolders.submissions(submissions);
    } catch (IllegalArgumentException | IOException e) {
      err.println("grade: " + e.getMessage());
      return 2;
    }
    if (found.isEmpty()) {
      err.println(
          "grade: no submissions in "
              + submissions
              + ": put each student's .java files in a folder of their own inside it");
      return 2;
    }
    Path subsReal = submissions.toAbsolutePath().normalize();
    Path outAbs = out.toAbsolutePath().normalize();
    if (outAbs.startsWith(subsReal)) {
      err.println("grade: put --out outside the submissions folder (students must not see it)");
      return 2;
    }
    Sandbox sandbox;
    if (unsafe) {
      sandbox = Sandbox.none();
      err.println(GradeReport.UNSAFE_WARNING);
    } else {
      try {
        sandbox = Sandbox.bubblewrap(bwrap);
      } catch (IllegalStateException e) {
        err.println(
            "grade: cannot isolate the submissions: "
                + e.getMessage()
                + ". Refusing to grade; --unsafe grades anyway (only for code you trust).");
        return 2;
      }
    }
    List<Path> toGrade = found;
    if (only != null) {
      toGrade = found.stream().filter(p -> SubmissionFolders.studentOf(p).equals(only)).toList();
      if (toGrade.isEmpty()) {
        err.println("grade: no submission called '" + only + "' in " + submissions);
        return 2;
      }
    }
    Path students = out.resolve("students");
    Grader grader =
        new Grader(
            a,
            Grader.Options.of(Duration.ofSeconds(timeoutSeconds), jobs, sandbox).in(Texts.of(lang)),
            students);
    o.printf(
        Locale.ROOT,
        "Grading %d submission(s) of '%s', %d at a time%s...%n",
        toGrade.size(),
        a.id(),
        Math.min(jobs, toGrade.size()),
        sandbox.isolated() ? ", each in a sandbox" : ", WITHOUT isolation (--unsafe)");
    o.flush();
    AtomicInteger done = new AtomicInteger();
    int total = toGrade.size();
    List<Grader.Result> graded =
        grader.gradeAll(
            toGrade,
            r -> {
              o.printf(
                  Locale.ROOT,
                  "  [%d/%d] %-20s %3d/%d  %s (%.1f s)%n",
                  done.incrementAndGet(),
                  total,
                  r.student(),
                  r.grade().score(),
                  r.grade().maxScore(),
                  r.status(),
                  r.seconds());
              o.flush();
            });
    List<Grader.Result> results = new ArrayList<>();
    if (only == null) {
      results.addAll(graded);
    } else {
      // the others as graded before, from their files in the report
      for (Path p : found) {
        String name = SubmissionFolders.studentOf(p);
        if (name.equals(only)) {
          results.add(graded.get(0));
          continue;
        }
        try {
          results.add(ResultFiles.read(students.resolve(SubmissionFolders.safeName(name)), name));
        } catch (IOException e) {
          err.println(
              "grade: " + name + " has no earlier result in " + out + " (grade the class first)");
        }
      }
    }
    GradeReport report = new GradeReport(a, results, lang, unsafe);
    Files.createDirectories(out);
    Files.writeString(out.resolve("report.txt"), report.text(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.md"), report.markdown(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.html"), report.html(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("gradebook.csv"), report.csv(), StandardCharsets.UTF_8);
    for (Grader.Result r : results) {
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
    return 0;
  }
}
