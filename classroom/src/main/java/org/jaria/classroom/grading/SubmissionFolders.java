package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * The submissions folder: one folder per student (its name is the student's name) with their {@code
 * .java} files, or one folder that holds {@code .java} files itself. Originals are only read: their
 * Java files are copied into a scratch folder.
 */
public final class SubmissionFolders {

  /** The most Java files, and bytes per file, copied from a submission. */
  static final int MAX_FILES = 200;

  static final long MAX_FILE_BYTES = 1 << 20;

  private SubmissionFolders() {}

  /**
   * The submissions in {@code folder}: its sub-folders, by name, or the folder itself if it holds
   * Java files directly.
   *
   * @throws IOException if the folder cannot be read
   */
  public static List<Path> submissions(Path folder) throws IOException {
    if (!Files.isDirectory(folder)) {
      throw new IOException("not a folder: " + folder);
    }
    try (Stream<Path> s = Files.list(folder)) {
      List<Path> entries = s.sorted().toList();
      if (entries.stream()
          .anyMatch(p -> p.toString().endsWith(".java") && Files.isRegularFile(p))) {
        return List.of(folder);
      }
      return entries.stream()
          .filter(p -> Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS))
          .filter(p -> !p.getFileName().toString().startsWith("."))
          .toList();
    }
  }

  /** The student's name: the submission folder's name. */
  public static String studentOf(Path dir) {
    return dir.getFileName() == null ? dir.toString() : dir.getFileName().toString();
  }

  /**
   * Copies the submission's .java files (regular files only: links are skipped, so a submission
   * cannot pull in another student's or the teacher's files) into {@code to}.
   */
  static void copySources(Path from, Path to) throws IOException {
    Files.createDirectories(to);
    int n = 0;
    try (Stream<Path> s = Files.walk(from, 8)) {
      for (Path p : s.sorted().toList()) {
        Path rel = from.relativize(p);
        if (!p.toString().endsWith(".java")
            || !Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)
            || hasLinkOrHidden(from, rel)
            || Files.size(p) > MAX_FILE_BYTES
            || ++n > MAX_FILES) {
          continue;
        }
        Path target = to.resolve(rel.toString());
        Files.createDirectories(target.getParent());
        Files.copy(p, target);
      }
    }
  }

  private static boolean hasLinkOrHidden(Path root, Path rel) {
    Path q = root;
    for (Path part : rel) {
      q = q.resolve(part);
      if (part.toString().startsWith(".") || Files.isSymbolicLink(q)) {
        return true;
      }
    }
    return false;
  }

  static String safeName(String s) {
    return s.replaceAll("[^A-Za-z0-9._-]", "_");
  }

  static void deleteTree(Path p) throws IOException {
    if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
      return;
    }
    try (Stream<Path> s = Files.walk(p)) {
      for (Path q : s.sorted(Comparator.reverseOrder()).toList()) {
        Files.delete(q);
      }
    }
  }
}
