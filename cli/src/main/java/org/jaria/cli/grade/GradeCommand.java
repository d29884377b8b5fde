package org.jaria.cli.grade;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.jaria.classroom.classgrading.ClassGrading;
import org.jaria.classroom.classgrading.GradeRequest;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.pack.PackTemplate;
import org.jaria.classroom.pack.Packs;
import org.jaria.classroom.platform.Platform;
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
          + " submission). Each is copied, then compiled and run in a JVM of its own inside a"
          + " bubblewrap sandbox (no network, no other files, limits on time, memory and threads)"
          + " while the simulator and the grade stay in this process. Writes report.txt,"
          + " report.md, report.html, gradebook.csv and students/NAME/feedback.txt."
    })
public final class GradeCommand implements Callable<Integer> {

  @Option(
      names = {"-a", "--assignment"},
      paramLabel = "ID",
      description = "The assignment: square, wall, goals, ball, or one of a --pack's.")
  String assignment;

  @Option(
      names = "--pack",
      paramLabel = "DIR|JAR",
      description =
          "A teacher's assignment pack to load besides the kit's (a folder as --new-pack writes"
              + " it, a folder of classes, or a jar); may be given more than once.")
  List<Path> packs = new ArrayList<>();

  @Option(
      names = "--new-pack",
      paramLabel = "DIR",
      description =
          "Write a starter assignment pack into the new folder DIR (its name is the pack's name)"
              + " and exit.")
  Path newPack;

  @Option(
      names = {"-o", "--out"},
      paramLabel = "DIR",
      description = "Where the reports and each student's files go (default: ${DEFAULT-VALUE}).",
      defaultValue = "grading-report")
  Path out;

  @Option(
      names = "--timeout",
      paramLabel = "SECONDS",
      description =
          "Real time allowed per student, compiling and running (default: ${DEFAULT-VALUE}).",
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
      names = "--gradescope",
      paramLabel = "DIR",
      arity = "0..1",
      fallbackValue = "/autograder/results",
      description =
          "Gradescope's autograder: grade SUBMISSIONS (default /autograder/submission) as one"
              + " submission and write DIR/results.json (default DIR: /autograder/results).")
  Path gradescope;

  @Option(
      names = "--github-classroom",
      description =
          "GitHub Classroom's autograding: grade SUBMISSIONS as one submission, print the"
              + " feedback, and write the reporter's result to $GITHUB_OUTPUT (or print it).")
  boolean githubClassroom;

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

  @Option(names = "--list", description = "List the assignments (the kit's and --pack's) and exit.")
  boolean list;

  @Parameters(paramLabel = "SUBMISSIONS", arity = "0..1", description = "The submissions folder.")
  Path submissions;

  @CommandLine.Spec CommandLine.Model.CommandSpec spec;

  @Override
  public Integer call() throws IOException {
    PrintWriter o = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    if (newPack != null) {
      return newPack(o, err);
    }
    if (list) {
      return list(o, err);
    }
    if (gradescope != null && githubClassroom) {
      err.println("grade: --gradescope or --github-classroom, not both");
      return ClassGrading.REFUSED;
    }
    Path subs = submissions;
    if (subs == null && gradescope != null) {
      subs = Path.of("/autograder/submission");
    }
    if (assignment == null || subs == null) {
      err.println("grade: give --assignment ID and a SUBMISSIONS folder (--list shows the ids)");
      return ClassGrading.REFUSED;
    }
    GradeRequest request =
        GradeRequest.of(assignment, subs, out)
            .withTimeout(Duration.ofSeconds(timeoutSeconds))
            .withJobs(jobs)
            .inLanguage(lang)
            .withBwrap(bwrap)
            .withPacks(packs)
            .withVersion(org.jaria.tools.ProjectVersion.get());
    if (only != null) {
      request = request.onlyStudent(only);
    }
    if (unsafe) {
      request = request.withoutIsolation();
    }
    if (gradescope != null) {
      request = request.reportingTo(Platform.GRADESCOPE, gradescope);
    } else if (githubClassroom) {
      String output = System.getenv("GITHUB_OUTPUT");
      request =
          request.reportingTo(
              Platform.GITHUB_CLASSROOM,
              output == null || output.isBlank() ? null : Path.of(output));
    }
    return ClassGrading.grade(request, o, err);
  }

  private int newPack(PrintWriter o, PrintWriter err) throws IOException {
    List<Path> files;
    try {
      files = PackTemplate.write(newPack);
    } catch (IllegalArgumentException e) {
      err.println("grade: " + e.getMessage());
      return ClassGrading.REFUSED;
    }
    o.println("Wrote the assignment pack " + newPack + ":");
    for (Path f : files) {
      o.println("  " + f);
    }
    String id = newPack.toAbsolutePath().normalize().getFileName().toString();
    o.println(
        "Grade its solution: ./jaria grade --pack "
            + newPack
            + " -a "
            + id
            + " "
            + newPack.resolve("solution"));
    o.flush();
    return 0;
  }

  private int list(PrintWriter o, PrintWriter err) throws IOException {
    try (Packs p = Packs.load(packs, Path.of(System.getProperty("java.io.tmpdir")))) {
      for (Assignment a : p.assignments()) {
        o.printf(Locale.ROOT, "%-7s %s (%d points)%n", a.id(), a.title(), a.points());
      }
    } catch (IllegalArgumentException | IllegalStateException e) {
      err.println("grade: " + e.getMessage());
      return ClassGrading.REFUSED;
    }
    o.flush();
    return 0;
  }
}
