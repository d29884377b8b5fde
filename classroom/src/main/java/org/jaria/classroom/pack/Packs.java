package org.jaria.classroom.pack;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.jaria.classroom.grading.Assignment;
import org.jaria.classroom.grading.Assignments;
import org.jaria.classroom.grading.SubmissionCompiler;
import org.jaria.classroom.sandbox.Cleanup;

/**
 * The assignment packs of one grading run: the kit's own, and the teachers' given to {@code jaria
 * grade --pack}, each found by {@link java.util.ServiceLoader} (see {@link Assignment}).
 *
 * <p>A pack is a jar, a folder of compiled classes (with {@code META-INF/services/...} at its top),
 * or a folder of sources as {@code jaria grade --new-pack} writes it: {@code src/} holds its Java
 * files and resources (its {@code META-INF/services} file, its catalogues, its maps), compiled here
 * into a temporary folder that is deleted when the packs are closed. The student's JVM gets the
 * pack's classes read-only, beside JAria's, so the assignment's student side runs there too.
 */
public final class Packs implements AutoCloseable {

  /** The file that lists a pack's assignments. */
  public static final String SERVICES = "META-INF/services/" + Assignment.class.getName();

  private final URLClassLoader loader;
  private final List<Assignment> assignments;
  private final Cleanup compiled;

  private Packs(URLClassLoader loader, List<Assignment> assignments, Cleanup compiled) {
    this.loader = loader;
    this.assignments = List.copyOf(assignments);
    this.compiled = compiled;
  }

  /**
   * The kit's assignments and those of {@code packs}; source packs are compiled into temporary
   * folders in {@code workRoot}.
   *
   * @throws IllegalArgumentException saying what is wrong, if a path is not a pack, a pack does not
   *     compile, or two assignments share an id
   * @throws IOException if a pack cannot be read or compiled into {@code workRoot}
   */
  public static Packs load(List<Path> packs, Path workRoot) throws IOException {
    if (packs.isEmpty()) {
      return new Packs(null, Assignments.all(), null);
    }
    Cleanup cleanup = Cleanup.open();
    try {
      List<URL> urls = new ArrayList<>();
      for (Path p : packs) {
        urls.add(url(classesOf(p, workRoot, cleanup)));
      }
      URLClassLoader loader =
          new URLClassLoader("packs", urls.toArray(URL[]::new), Packs.class.getClassLoader());
      List<Assignment> all;
      try {
        all = Assignments.all(loader);
      } catch (IllegalStateException e) {
        loader.close();
        throw new IllegalArgumentException(e.getMessage(), e);
      }
      return new Packs(loader, all, cleanup);
    } catch (IOException | RuntimeException e) {
      cleanup.close();
      throw e;
    }
  }

  /** The class loader of the teachers' packs (on top of the kit's), or the kit's if none. */
  public URLClassLoader loader() {
    return loader != null
        ? loader
        : new URLClassLoader("kit", new URL[0], Packs.class.getClassLoader());
  }

  /** Every assignment: the kit's first, then the packs', in the order they list them. */
  public List<Assignment> assignments() {
    return assignments;
  }

  /**
   * The assignment called {@code id}.
   *
   * @throws IllegalArgumentException naming the ids there are, if there is none by that id
   */
  public Assignment byId(String id) {
    return Assignments.byId(id, assignments);
  }

  /** Where the classes of pack {@code p} are: the jar or folder itself, or its compiled sources. */
  private static Path classesOf(Path p, Path workRoot, Cleanup cleanup) throws IOException {
    if (Files.isRegularFile(p) && p.toString().endsWith(".jar")) {
      return p;
    }
    if (Files.isDirectory(p.resolve("src"))) {
      return compile(p, workRoot, cleanup);
    }
    if (Files.isRegularFile(p.resolve(SERVICES))) {
      return p;
    }
    throw new IllegalArgumentException(
        (Files.exists(p) ? "not an assignment pack: " : "no assignment pack at ")
            + p
            + ": a pack is a jar, or a folder with src/ (its sources) or "
            + SERVICES
            + " (its classes); ./jaria grade --new-pack DIR writes one to start from");
  }

  /** Compiles a source pack's src/ into a temporary folder, its resources copied beside. */
  private static Path compile(Path pack, Path workRoot, Cleanup cleanup) throws IOException {
    Path src = pack.resolve("src");
    if (!Files.isRegularFile(src.resolve(SERVICES))) {
      throw new IllegalArgumentException(
          "the pack in "
              + pack
              + " lists no assignment: add src/"
              + SERVICES
              + " with its Assignment classes' names, one a line");
    }
    Files.createDirectories(workRoot);
    Path out = cleanup.track(Files.createTempDirectory(workRoot, "jaria-pack-"));
    SubmissionCompiler.Result r =
        SubmissionCompiler.compile(src, out, SubmissionCompiler.classPath());
    if (!r.ok()) {
      throw new IllegalArgumentException(
          "the pack in " + pack + " does not compile:\n" + r.errors());
    }
    try (Stream<Path> s = Files.walk(src)) {
      for (Path f : s.filter(Files::isRegularFile).toList()) {
        if (!f.toString().endsWith(".java")) {
          Path to = out.resolve(src.relativize(f).toString());
          Files.createDirectories(to.getParent());
          Files.copy(f, to);
        }
      }
    }
    readableByAll(out);
    return out;
  }

  /** When the grader runs as root, students' JVMs run as other users: they must read the pack. */
  private static void readableByAll(Path dir) throws IOException {
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.toList()) {
        Files.setPosixFilePermissions(
            p, PosixFilePermissions.fromString(Files.isDirectory(p) ? "rwxr-xr-x" : "rw-r--r--"));
      }
    } catch (UnsupportedOperationException e) {
      // not a POSIX file system: no other users to think of
    }
  }

  private static URL url(Path p) {
    try {
      return p.toAbsolutePath().toUri().toURL();
    } catch (MalformedURLException e) {
      throw new IllegalArgumentException("not a path for classes: " + p, e);
    }
  }

  /** Closes the packs' class loader and deletes the compiled sources. */
  @Override
  public void close() throws IOException {
    try {
      if (loader != null) {
        loader.close();
      }
    } finally {
      if (compiled != null) {
        compiled.close();
      }
    }
  }
}
