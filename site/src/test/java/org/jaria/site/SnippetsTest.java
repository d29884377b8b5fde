package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SnippetsTest {

  private static final String SOURCE =
      """
      package x;

      import java.util.List;

      public class A {
        // tag::field[]
        private int n = 1; // braces in comments do not count: {
        // end::field[]

        @Override
        public String toString() {
          String s = "}{";
          char c = '}';
          String t = \"""
              { not code
              \""";
          return s + c + t;
        }

        static int twice(int x) {
          return 2 * x;
        }
      }
      """;

  @Test
  void tagsMembersAndWholeFiles(@TempDir Path root) throws IOException {
    Files.writeString(root.resolve("A.java"), SOURCE);
    Snippets s = new Snippets(root);
    assertEquals("private int n = 1; // braces in comments do not count: {", s.get("A.java#field"));
    assertEquals("static int twice(int x) {\n  return 2 * x;\n}", s.get("A.java#twice"));
    String ts = s.get("A.java#toString");
    assertTrue(ts.startsWith("@Override\npublic String toString() {"), ts);
    assertTrue(ts.endsWith("return s + c + t;\n}"), ts);
    assertTrue(s.get("A.java").startsWith("import java.util.List;\n\npublic class A {"));
    assertThrows(IllegalArgumentException.class, () -> s.get("A.java#nothing"));
    assertThrows(IllegalArgumentException.class, () -> s.get("B.java#x"));
  }

  @Test
  void nestedTagMarkersLeaveNoDoubleBlankLines(@TempDir Path root) throws IOException {
    Files.writeString(
        root.resolve("B.java"),
        "// tag::all[]\nint a;\n\n// tag::b[]\n\nint b;\n// end::b[]\n// end::all[]\n");
    assertEquals("int a;\n\nint b;", new Snippets(root).get("B.java#all"));
  }

  @Test
  void driftedBlocksAreFoundAndRewritten(@TempDir Path root) throws IOException {
    Files.writeString(root.resolve("A.java"), SOURCE);
    String md = "# T\n\n<!-- snippet: A.java#twice -->\n```java\nold\n```\n";
    SnippetSync.Result r = new SnippetSync(root).sync("t.md", md);
    assertEquals(1, r.drifts().size());
    assertTrue(r.text().contains("```java\nstatic int twice(int x) {"), r.text());
    assertEquals(0, new SnippetSync(root).sync("t.md", r.text()).drifts().size());
  }
}
