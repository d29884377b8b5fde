package org.jaria.classroom.grading;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.stream.Stream;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Compiles a student's Java files in-process (javax.tools), against JAria's own class path, and
 * reports compile errors the way javac prints them: file, line, message.
 */
public final class SubmissionCompiler {

  /** At most this many errors are reported; the first ones are the ones to fix. */
  static final int MAX_ERRORS = 10;

  private SubmissionCompiler() {}

  /**
   * What came of compiling.
   *
   * @param ok whether it compiled
   * @param classNames the binary names of the classes written (empty if not ok)
   * @param errors the compile errors, one per line, or why nothing was compiled
   */
  public record Result(boolean ok, List<String> classNames, String errors) {

    /** Copies. */
    public Result {
      classNames = List.copyOf(classNames);
    }
  }

  /**
   * The class path solutions compile and run against: this JVM's class path plus the jars (or
   * folders) that hold JAria's own modules, so it works from the {@code jaria} launcher, a test
   * runner and an IDE alike.
   */
  public static String classPath() {
    return classPath(null);
  }

  /**
   * {@link #classPath()} and where {@code a}'s classes come from (a pack's folder or jar), so a
   * solution may use the pack's own types; {@code a} may be null.
   */
  public static String classPath(Assignment a) {
    Set<String> parts = new LinkedHashSet<>();
    String own = System.getProperty("java.class.path", "");
    for (int from = 0; from <= own.length(); ) {
      int to = own.indexOf(File.pathSeparatorChar, from);
      to = to < 0 ? own.length() : to;
      if (to > from) {
        parts.add(own.substring(from, to));
      }
      from = to + 1;
    }
    List<Class<?>> anchors =
        new ArrayList<>(
            List.of(
                SubmissionCompiler.class,
                org.jaria.robot.ArRobot.class,
                org.jaria.sim.SimWorld.class,
                org.jaria.arnl.ArPathPlanningTask.class,
                org.jaria.acts.ArACTS_1_2.class,
                org.slf4j.LoggerFactory.class));
    if (a != null) {
      anchors.add(a.getClass());
    }
    for (Class<?> anchor : anchors) {
      try {
        var src = anchor.getProtectionDomain().getCodeSource();
        if (src != null) {
          parts.add(Path.of(src.getLocation().toURI()).toString());
        }
      } catch (URISyntaxException | SecurityException | IllegalArgumentException e) {
        // not a file location: the class path above has to do
      }
    }
    return String.join(File.pathSeparator, parts);
  }

  /**
   * Compiles every {@code .java} file under {@code sourceDir} into {@code outDir}.
   *
   * @throws IllegalStateException if this Java has no compiler (a JRE rather than a JDK)
   * @throws IOException if the folders cannot be read or written
   */
  public static Result compile(Path sourceDir, Path outDir, String classPath) throws IOException {
    JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
    if (javac == null) {
      throw new IllegalStateException(
          "this Java ("
              + System.getProperty("java.home")
              + ") has no compiler: grading needs a JDK, not a JRE; set JAVA_HOME to a JDK 17"
              + " or newer");
    }
    List<Path> sources = javaFiles(sourceDir);
    if (sources.isEmpty()) {
      return new Result(false, List.of(), "no .java files in " + sourceDir);
    }
    Files.createDirectories(outDir);
    DiagnosticCollector<JavaFileObject> diags = new DiagnosticCollector<>();
    StringWriter out = new StringWriter();
    boolean ok;
    try (StandardJavaFileManager fm =
        javac.getStandardFileManager(diags, Locale.ROOT, StandardCharsets.UTF_8)) {
      List<String> options =
          List.of(
              "-d",
              outDir.toString(),
              "-classpath",
              classPath,
              "-encoding",
              "UTF-8",
              "--release",
              "17",
              "-proc:none",
              "-Xlint:none");
      ok =
          javac
              .getTask(out, fm, diags, options, null, fm.getJavaFileObjectsFromPaths(sources))
              .call();
    }
    StringBuilder errors = new StringBuilder();
    int n = 0;
    for (Diagnostic<? extends JavaFileObject> d : diags.getDiagnostics()) {
      if (d.getKind() != Diagnostic.Kind.ERROR) {
        continue;
      }
      if (++n > MAX_ERRORS) {
        errors.append("... and more errors\n");
        break;
      }
      String file = d.getSource() == null ? "?" : Path.of(d.getSource().toUri()).getFileName() + "";
      errors
          .append(file)
          .append(':')
          .append(d.getLineNumber())
          .append(": error: ")
          .append(d.getMessage(Locale.ROOT).replace('\n', ' '))
          .append('\n');
    }
    if (!ok && errors.length() == 0) {
      errors.append(out.toString().strip());
    }
    return new Result(ok, ok ? classNames(outDir) : List.of(), errors.toString().strip());
  }

  /** The .java files under {@code dir}, sorted, skipping hidden folders. */
  static List<Path> javaFiles(Path dir) throws IOException {
    try (Stream<Path> s = Files.walk(dir)) {
      return s.filter(p -> p.toString().endsWith(".java"))
          .filter(Files::isRegularFile)
          .filter(p -> !isHidden(dir.relativize(p)))
          .sorted()
          .toList();
    }
  }

  private static boolean isHidden(Path relative) {
    for (Path part : relative) {
      if (part.toString().startsWith(".")) {
        return true;
      }
    }
    return false;
  }

  /** The binary names of the classes under {@code classesDir}, sorted. */
  public static List<String> classNames(Path classesDir) throws IOException {
    List<String> names = new ArrayList<>();
    try (Stream<Path> s = Files.walk(classesDir)) {
      for (Path p : s.filter(f -> f.toString().endsWith(".class")).sorted().toList()) {
        String rel = classesDir.relativize(p).toString();
        names.add(
            rel.substring(0, rel.length() - ".class".length()).replace(File.separatorChar, '.'));
      }
    }
    return names;
  }
}
