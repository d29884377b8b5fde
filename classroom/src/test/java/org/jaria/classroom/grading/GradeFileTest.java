package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GradeFileTest {

  @Test
  void aGradeSurvivesTheTripThroughItsFile(@TempDir Path tmp) throws IOException {
    Grade g =
        new Grade(
            "square",
            List.of(
                Check.pass("program ends", 1, "your program returned"),
                Check.fail(
                    "compiles", 9, "Square.java:3: error:\tcannot find symbol\nback\\slash")));
    Path f = tmp.resolve("grade.txt");
    GradeFile.write(g, f);
    assertEquals(g, GradeFile.read(f));
  }

  @Test
  void aDamagedFileIsAnErrorNotAGrade(@TempDir Path tmp) throws IOException {
    Path f = tmp.resolve("grade.txt");
    Files.writeString(f, "something else\n");
    assertThrows(IOException.class, () -> GradeFile.read(f));
    Files.writeString(f, "jaria-grade 1 square\nnot\ta check\n");
    assertThrows(IOException.class, () -> GradeFile.read(f));
  }
}
