package org.jaria.apps;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code ./mvnw verify -Pfast} leaves out the tests tagged "gui": that only works if every test
 * that opens JavaFX carries the tag, which this test checks over this module's test sources.
 */
class TestTagsTest {

  @Test
  void everyJavaFxTestIsTaggedGui() throws IOException {
    Path tests = Path.of("src/test/java");
    assertTrue(Files.isDirectory(tests), "run from the module folder: " + tests.toAbsolutePath());
    List<String> untagged = new ArrayList<>();
    int fx = 0;
    try (Stream<Path> s = Files.walk(tests)) {
      for (Path f :
          s.filter(p -> p.toString().endsWith("Test.java"))
              .filter(p -> !p.endsWith("TestTagsTest.java")) // names what it looks for
              .toList()) {
        String src = Files.readString(f, StandardCharsets.UTF_8);
        boolean opensJavaFx =
            src.contains("ApplicationExtension") || src.contains("import javafx.");
        if (opensJavaFx) {
          fx++;
          if (!src.contains("@Tag(\"gui\")")) {
            untagged.add(tests.relativize(f).toString());
          }
        }
      }
    }
    assertTrue(fx >= 5, "found the JavaFX tests: " + fx);
    assertEquals(List.of(), untagged, "JavaFX tests without @Tag(\"gui\")");
  }
}
