package org.jaria.classroom.kit;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Grade;
import org.jaria.classroom.grading.Grading;

/** The kit's files (classroom/assignments/ID/{starter,solution}) graded as submissions are. */
public final class Kit {

  private Kit() {}

  /** The folder of an assignment's starter or solution. */
  public static Path folder(String assignment, String which) {
    Path p = Path.of("assignments", assignment, which);
    if (!Files.isDirectory(p)) {
      throw new IllegalStateException("missing " + p.toAbsolutePath());
    }
    return p;
  }

  /** Compiles and grades the kit's {@code which} ("starter" or "solution") in this JVM. */
  public static Grade grade(Assignment a, String which, Path work) throws IOException {
    return Grading.compileAndGrade(a, folder(a.id(), which), work);
  }

  /** Compiles and grades one source file, given as text, in this JVM. */
  public static Grade gradeSource(Assignment a, String fileName, String source, Path work)
      throws IOException {
    Path src = work.resolve("src");
    Files.createDirectories(src);
    Files.writeString(src.resolve(fileName), source, StandardCharsets.UTF_8);
    return Grading.compileAndGrade(a, src, work.resolve("classes"));
  }
}
