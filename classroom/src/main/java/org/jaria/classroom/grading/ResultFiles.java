package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * One student's result on disk, in their folder of the report: grade.txt (the checks) and
 * status.txt (status and seconds, then the student's name), written by the grader only. Re-grading
 * one student reads the others' back from here, and checks that each folder is still the student's.
 */
public final class ResultFiles {

  private ResultFiles() {}

  static void write(Path studentDir, Grader.Result r) throws IOException {
    Files.createDirectories(studentDir);
    GradeFile.write(r.grade(), studentDir.resolve("grade.txt"));
    Files.writeString(
        studentDir.resolve("status.txt"),
        String.format(
            Locale.ROOT,
            "%s %.2f%nstudent %s%n",
            r.status(),
            r.seconds(),
            GradeFile.escape(r.student())),
        StandardCharsets.UTF_8);
  }

  /**
   * Reads {@code student}'s result back from {@code studentDir}.
   *
   * @throws IOException if the files are missing or not the grader's
   */
  public static Grader.Result read(Path studentDir, String student) throws IOException {
    Grade g = GradeFile.read(studentDir.resolve("grade.txt"));
    List<String> lines =
        Files.readAllLines(studentDir.resolve("status.txt"), StandardCharsets.UTF_8);
    String status = lines.isEmpty() ? "" : lines.get(0).strip();
    if (lines.size() > 1
        && lines.get(1).startsWith("student ")
        && !GradeFile.unescape(lines.get(1).substring(8)).equals(student)) {
      throw new IOException(
          studentDir + " holds the result of another student: grade the class again");
    }
    int space = status.indexOf(' ');
    String[] f =
        space < 0
            ? new String[] {status}
            : new String[] {status.substring(0, space), status.substring(space + 1)};
    try {
      return new Grader.Result(
          student,
          Status.valueOf(f[0]),
          g,
          f.length > 1 ? Double.parseDouble(f[1]) : 0,
          studentDir.resolve("output.txt"));
    } catch (IllegalArgumentException e) {
      throw new IOException("not a status file: " + studentDir.resolve("status.txt"), e);
    }
  }
}
