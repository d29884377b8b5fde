package org.jaria.classroom.pack;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Writes a starter pack ({@code jaria grade --new-pack DIR}): a compiling assignment with one check
 * (drive 1 m and stop), its English and Spanish sentences, a starter and a solution, and a JUnit
 * test that the solution earns full marks, the starter less, and moving the robot without driving
 * nothing. The folder's name is the pack's name: the assignment's id and its Java package.
 */
public final class PackTemplate {

  private PackTemplate() {}

  /**
   * Writes the starter pack into the new folder {@code dir}.
   *
   * @return the files written, relative to {@code dir}
   * @throws IllegalArgumentException if the folder's name is not a pack name, or it exists
   * @throws IOException if a file cannot be written
   */
  public static List<Path> write(Path dir) throws IOException {
    Path abs = dir.toAbsolutePath().normalize();
    String name = abs.getFileName() == null ? "" : abs.getFileName().toString();
    if (!name.matches("[a-z][a-z0-9]{0,30}")) {
      throw new IllegalArgumentException(
          "name the pack's folder with lowercase letters and digits, starting with a letter"
              + " (e.g. parking): '"
              + name
              + "' is also its Java package and its assignment's id");
    }
    if (Files.exists(dir)) {
      throw new IllegalArgumentException(dir + " already exists: name a new folder for the pack");
    }
    String cls = name.substring(0, 1).toUpperCase(Locale.ROOT) + name.substring(1);
    List<String[]> files =
        List.of(
            new String[] {"README.md.txt", "README.md"},
            new String[] {"Assignment.java.txt", "src/" + name + "/" + cls + "Assignment.java"},
            new String[] {"en.properties.txt", "src/" + name + "/" + name + "_en.properties"},
            new String[] {"es.properties.txt", "src/" + name + "/" + name + "_es.properties"},
            new String[] {"Starter.java.txt", "starter/" + cls + ".java"},
            new String[] {"Solution.java.txt", "solution/" + cls + ".java"},
            new String[] {"Test.java.txt", "test/" + name + "/" + cls + "AssignmentTest.java"});
    List<Path> written = new ArrayList<>();
    for (String[] f : files) {
      String text =
          template(f[0])
              .replace("__PACK__", name)
              .replace("__Class__", cls)
              .replace("__DIR__", dir.toString());
      written.add(put(dir, f[1], text));
    }
    written.add(put(dir, "src/" + Packs.SERVICES, name + "." + cls + "Assignment\n"));
    return written;
  }

  private static Path put(Path dir, String rel, String text) throws IOException {
    Path p = dir.resolve(rel);
    Files.createDirectories(p.getParent());
    Files.writeString(p, text, StandardCharsets.UTF_8);
    return Path.of(rel);
  }

  private static String template(String name) {
    try (InputStream in = PackTemplate.class.getResourceAsStream("template/" + name)) {
      if (in == null) {
        throw new IllegalStateException("the pack template " + name + " is missing from the jar");
      }
      return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }
}
