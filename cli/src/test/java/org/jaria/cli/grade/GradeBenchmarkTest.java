package org.jaria.cli.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The benchmark's class and its comparison, as values (the timed run itself is {@code jaria bench
 * grade}, never a test).
 */
class GradeBenchmarkTest {

  @Test
  void theClassHasTheMixOfTheIssue(@TempDir Path tmp) throws IOException {
    GradeBenchmark.writeClass(tmp, GradeBenchmark.FULL, "class A { int a; }", "class B {}");
    try (Stream<Path> s = Files.list(tmp)) {
      List<String> names = s.map(p -> p.getFileName().toString()).sorted().toList();
      assertEquals(60, names.size());
      assertEquals(30, names.stream().filter(n -> n.startsWith("good")).count());
      assertEquals(12, names.stream().filter(n -> n.startsWith("bad")).count());
      assertEquals(5, names.stream().filter(n -> n.startsWith("broken")).count());
      assertEquals(5, names.stream().filter(n -> n.startsWith("hangctor")).count());
      assertEquals(8, names.stream().filter(n -> n.startsWith("busywait")).count());
    }
    assertEquals("class A { int a }", Files.readString(tmp.resolve("broken01/Square.java")));
  }

  @Test
  void twoReportsDifferInTheFilesThatDiffer(@TempDir Path tmp) throws IOException {
    for (String r : List.of("a", "b")) {
      Files.createDirectories(tmp.resolve(r).resolve("students/ana"));
      Files.writeString(tmp.resolve(r).resolve("gradebook.csv"), "student\nana\n");
      Files.writeString(tmp.resolve(r).resolve("students/ana/grade.txt"), "10");
    }
    assertEquals(List.of(), GradeBenchmark.differences(tmp.resolve("a"), tmp.resolve("b")));
    Files.writeString(tmp.resolve("b/students/ana/grade.txt"), "9");
    assertEquals(
        List.of("students/ana/grade.txt"),
        GradeBenchmark.differences(tmp.resolve("a"), tmp.resolve("b")));
  }
}
