package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every {@code ./jaria demo ...} line of the documentation runs, for a second each (a class of its
 * own beside {@link DocsCommandsTest}, which checks that every line parses and runs the rest).
 */
@Tag("slow")
class DocsDemoCommandsTest {

  @Test
  void everyDemoTheDocsShowRunsForASecond(@TempDir Path tmp) throws IOException {
    DocCommands docs = new DocCommands();
    DocCommands.Result r = docs.check(docs.lines("./jaria demo"), "demo"::equals, tmp);
    assertEquals(List.of(), r.failures());
    assertTrue(r.ran() >= 5, "only " + r.ran() + " demos ran");
  }
}
