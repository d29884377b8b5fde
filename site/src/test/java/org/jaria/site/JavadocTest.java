package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import javax.tools.DocumentationTool;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A quick stand-in for the {@code -Pjavadoc} build (which documents every module and takes tens of
 * seconds): the Javadoc tool runs, with the same offline options, over the classroom kit's public
 * API, which students read first, and must succeed and write its index.
 */
class JavadocTest {

  @Test
  void theStudentFacingApiDocumentsCleanly(@TempDir Path out) throws IOException {
    Path root = Repo.root();
    DocumentationTool javadoc = ToolProvider.getSystemDocumentationTool();
    List<Path> sources;
    try (Stream<Path> s = Files.walk(root.resolve("classroom/src/main/java/org/jaria/classroom"))) {
      sources = s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
    }
    StringWriter log = new StringWriter();
    boolean ok;
    try (StandardJavaFileManager fm =
        javadoc.getStandardFileManager(null, Locale.ROOT, StandardCharsets.UTF_8)) {
      ok =
          javadoc
              .getTask(
                  log,
                  fm,
                  null,
                  null,
                  List.of(
                      "-d",
                      out.toString(),
                      "-classpath",
                      System.getProperty("java.class.path"),
                      "-Xdoclint:all,-missing",
                      "-quiet",
                      "-encoding",
                      "UTF-8"),
                  fm.getJavaFileObjectsFromPaths(sources))
              .call();
    }
    assertTrue(ok, "javadoc failed:\n" + log);
    assertEquals("", log.toString().strip(), "javadoc warnings");
    assertTrue(Files.isRegularFile(out.resolve("org/jaria/classroom/RobotProgram.html")));
  }
}
