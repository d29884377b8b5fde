package org.jaria.tools.grade;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Assignments;
import org.jaria.classroom.grading.ClassGrading;
import org.jaria.classroom.grading.GradeRequest;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code jaria grade}: grades a folder of student submissions on the simulator. The options become
 * a {@link GradeRequest}, which the classroom library's {@link ClassGrading} carries out.
 */
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
      return ClassGrading.REFUSED;
    }
    GradeRequest request =
        new GradeRequest(
            assignment,
            submissions,
            out,
            Duration.ofSeconds(timeoutSeconds),
            jobs,
            only,
            lang,
            unsafe,
            bwrap);
    return ClassGrading.grade(request, o, err);
  }
}
