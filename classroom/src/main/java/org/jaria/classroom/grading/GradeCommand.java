package org.jaria.classroom.grading;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
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
          + " submission). Each is compiled here and graded in a JVM of its own with a time"
          + " limit; the report is printed and written as report.txt, report.md and report.html."
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
      description = "Where the reports and each student's output go (default: ${DEFAULT-VALUE}).",
      defaultValue = "grading-report")
  Path out;

  @Option(
      names = "--timeout",
      paramLabel = "SECONDS",
      description = "Real time allowed per submission (default: ${DEFAULT-VALUE}).",
      defaultValue = "120")
  long timeoutSeconds;

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
    Assignment a;
    List<Path> found;
    try {
      a = Assignments.byId(assignment);
      found = Grader.submissions(submissions);
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
    if (timeoutSeconds <= 0) {
      err.println("grade: --timeout must be positive");
      return 2;
    }
    o.printf(Locale.ROOT, "Grading %d submission(s) of '%s'...%n", found.size(), a.id());
    o.flush();
    Grader grader = new Grader(a, Duration.ofSeconds(timeoutSeconds), out.resolve("students"));
    List<Grader.Result> results =
        grader.gradeAll(
            submissions,
            r -> {
              o.printf(
                  Locale.ROOT,
                  "  %-20s %3d/%d  %s (%.1f s)%n",
                  r.student(),
                  r.grade().score(),
                  r.grade().maxScore(),
                  r.status(),
                  r.seconds());
              o.flush();
            });
    GradeReport report = new GradeReport(a, results);
    Files.createDirectories(out);
    Files.writeString(out.resolve("report.txt"), report.text(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.md"), report.markdown(), StandardCharsets.UTF_8);
    Files.writeString(out.resolve("report.html"), report.html(), StandardCharsets.UTF_8);
    o.println();
    o.print(report.text());
    o.println();
    o.println(
        "Reports written to " + out.toAbsolutePath().normalize() + " (report.md, .html, .txt)");
    o.flush();
    return 0;
  }
}
