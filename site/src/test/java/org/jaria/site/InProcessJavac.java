package org.jaria.site;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import javax.tools.JavaCompiler;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/** javac run inside the test's JVM, for the tests that check what the build's compile steps do. */
final class InProcessJavac {

  private InProcessJavac() {}

  /**
   * Whether javac compiled the sources, and what it printed.
   *
   * @param ok true when javac reported success
   * @param log javac's messages
   */
  record Result(boolean ok, String log) {}

  /** Compiles {@code sources} with javac's {@code options} (e.g. {@code -d} and a folder). */
  static Result compile(List<String> options, Path... sources) throws IOException {
    JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
    StringWriter log = new StringWriter();
    try (StandardJavaFileManager fm =
        javac.getStandardFileManager(null, Locale.ROOT, StandardCharsets.UTF_8)) {
      boolean ok =
          javac.getTask(log, fm, null, options, null, fm.getJavaFileObjects(sources)).call();
      return new Result(ok, log.toString());
    }
  }
}
