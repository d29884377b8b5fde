package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The guides' Java can not rot: every Java block is quoted from a compiled, tested source. */
class DocsSnippetsTest {

  private final Path root = Repo.root();

  /**
   * With {@code -Djaria.docs.update=true} the blocks are first rewritten from their sources (how a
   * writer refreshes the guides after changing a sample).
   */
  @Test
  void everyQuotedBlockEqualsItsSource() throws IOException {
    if (Boolean.getBoolean("jaria.docs.update")) {
      SnippetSync.run(root, true, System.out);
    }
    List<SnippetSync.Drift> drifts = new SnippetSync(root).check(root);
    assertTrue(
        drifts.isEmpty(),
        "code blocks that differ from their sources (fix the source, or refresh the guides:"
            + " ./mvnw -pl site -am test -Dtest=DocsSnippetsTest -Djaria.docs.update=true"
            + " -Dsurefire.failIfNoSpecifiedTests=false):\n"
            + drifts.stream().map(Object::toString).collect(Collectors.joining("\n")));
  }

  @Test
  void everyJavaBlockIsAQuotedSnippet() throws IOException {
    List<String> unquoted = new ArrayList<>();
    int quoted = 0;
    for (Path rel : DocFiles.list(root)) {
      List<String> lines = Files.readAllLines(root.resolve(rel), StandardCharsets.UTF_8);
      for (int i = 0; i < lines.size(); i++) {
        if (lines.get(i).strip().equals("```java")) {
          boolean marked = i > 0 && SnippetSync.MARKER.matcher(lines.get(i - 1)).matches();
          if (marked) {
            quoted++;
          } else {
            unquoted.add(rel + ":" + (i + 1));
          }
        }
      }
    }
    assertEquals(List.of(), unquoted, "Java blocks without a <!-- snippet: ... --> marker");
    assertTrue(quoted >= 15, "the guides quote " + quoted + " Java snippets");
  }
}
