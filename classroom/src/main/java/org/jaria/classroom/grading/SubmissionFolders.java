package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * The submissions folder: one folder per student (its name is the student's name) with their {@code
 * .java} files, or, when it has no folders in it, one student's {@code .java} files. Files beside
 * the students' folders are listed and skipped; a student's folder that is a link is reported, not
 * followed. Originals are only read: their Java files are copied into a scratch folder, within
 * limits that are reported when a submission goes over them.
 */
public final class SubmissionFolders {

  /** The most Java files copied from a submission. */
  static final int MAX_FILES = 200;

  /** The most bytes of one Java file. */
  static final long MAX_FILE_BYTES = 1 << 20;

  /** The most bytes of all of a submission's Java files together. */
  static final long MAX_TOTAL_BYTES = 4L << 20;

  /** The most files and folders looked at in one submission. */
  static final int MAX_ENTRIES = 20_000;

  private SubmissionFolders() {}

  /**
   * One student's submission.
   *
   * @param student the student's name (their folder's name)
   * @param dir their folder
   * @param link whether the folder is a link (reported, not followed)
   */
  public record Submission(String student, Path dir, boolean link) {}

  /**
   * What a submissions folder holds.
   *
   * @param submissions the students' submissions, by name
   * @param skipped what was skipped beside them, one sentence each for the teacher
   */
  public record Scan(List<Submission> submissions, List<String> skipped) {

    /** Copies. */
    public Scan {
      submissions = List.copyOf(submissions);
      skipped = List.copyOf(skipped);
    }
  }

  /**
   * The submissions in {@code folder}: its folders, by name, or the folder itself if it has no
   * folders but holds Java files.
   *
   * @throws IOException if the folder cannot be read
   */
  public static Scan scan(Path folder) throws IOException {
    if (!Files.isDirectory(folder)) {
      throw new IOException("not a folder: " + folder);
    }
    List<Path> entries;
    try (Stream<Path> s = Files.list(folder)) {
      entries = s.filter(p -> !p.getFileName().toString().startsWith(".")).sorted().toList();
    }
    boolean anyFolder = entries.stream().anyMatch(Files::isDirectory);
    if (!anyFolder
        && entries.stream()
            .anyMatch(p -> p.toString().endsWith(".java") && Files.isRegularFile(p))) {
      return new Scan(List.of(new Submission(studentOf(folder), folder, false)), List.of());
    }
    List<Submission> subs = new ArrayList<>();
    List<String> skipped = new ArrayList<>();
    for (Path p : entries) {
      if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
        subs.add(new Submission(studentOf(p), p, false));
      } else if (Files.isSymbolicLink(p) && Files.isDirectory(p)) {
        subs.add(new Submission(studentOf(p), p, true));
      } else {
        skipped.add(
            "skipped "
                + p.getFileName()
                + ": a file beside the students' folders (each student's files go in a folder of"
                + " their own)");
      }
    }
    return new Scan(subs, skipped);
  }

  /**
   * {@code folder} as one student's submission, whatever it holds (where a platform hands over one
   * submission at a time).
   *
   * @throws IOException if it is not a folder
   */
  public static Scan single(Path folder) throws IOException {
    if (!Files.isDirectory(folder)) {
      throw new IOException("not a folder: " + folder);
    }
    return new Scan(List.of(new Submission(studentOf(folder), folder, false)), List.of());
  }

  /** The submissions' folders in {@code folder} (see {@link #scan}). */
  public static List<Path> submissions(Path folder) throws IOException {
    return scan(folder).submissions().stream().map(Submission::dir).toList();
  }

  /** The student's name: the submission folder's name. */
  public static String studentOf(Path dir) {
    Path abs = dir.toAbsolutePath().normalize();
    return abs.getFileName() == null ? abs.toString() : abs.getFileName().toString();
  }

  /**
   * What copying a submission found.
   *
   * @param files how many Java files were copied
   * @param tooLarge what is over the limits (nothing is copied then), one sentence each
   * @param links the Java files that are links and were not copied, relative to the submission
   */
  record Copied(int files, List<String> tooLarge, List<String> links) {}

  /**
   * Copies the submission's .java files into {@code to}: regular files only (links are not
   * followed, so a submission cannot pull in another student's or the teacher's files), nothing in
   * hidden folders, and nothing at all if the submission is over the limits, which are then named.
   */
  static Copied copySources(Path from, Path to) throws IOException {
    List<Path> sources = new ArrayList<>();
    List<String> links = new ArrayList<>();
    List<String> tooLarge = new ArrayList<>();
    long[] total = {0};
    int[] entries = {0};
    Files.walkFileTree(
        from,
        new SimpleFileVisitor<>() {
          @Override
          public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes a) {
            if (++entries[0] > MAX_ENTRIES) {
              return FileVisitResult.TERMINATE;
            }
            return !d.equals(from) && d.getFileName().toString().startsWith(".")
                ? FileVisitResult.SKIP_SUBTREE
                : FileVisitResult.CONTINUE;
          }

          @Override
          public FileVisitResult visitFile(Path f, BasicFileAttributes a) {
            if (++entries[0] > MAX_ENTRIES) {
              return FileVisitResult.TERMINATE;
            }
            String name = f.getFileName().toString();
            if (!name.endsWith(".java") || name.startsWith(".")) {
              return FileVisitResult.CONTINUE;
            }
            String rel = from.relativize(f).toString();
            if (a.isSymbolicLink()) {
              links.add(rel);
            } else if (a.isRegularFile()) {
              sources.add(f);
              total[0] += a.size();
              if (a.size() > MAX_FILE_BYTES) {
                tooLarge.add(
                    rel
                        + " is "
                        + Fmt.bytes(a.size())
                        + " (at most "
                        + Fmt.bytes(MAX_FILE_BYTES)
                        + " per file)");
              }
            }
            return FileVisitResult.CONTINUE;
          }

          @Override
          public FileVisitResult visitFileFailed(Path f, IOException e) {
            return FileVisitResult.CONTINUE;
          }
        });
    if (entries[0] > MAX_ENTRIES) {
      tooLarge.add(
          0,
          "it holds more than " + MAX_ENTRIES + " files and folders (only Java files are needed)");
    }
    if (sources.size() > MAX_FILES) {
      tooLarge.add(0, sources.size() + " .java files (at most " + MAX_FILES + ")");
    }
    if (total[0] > MAX_TOTAL_BYTES) {
      tooLarge.add(
          Fmt.bytes(total[0])
              + " of .java files together (at most "
              + Fmt.bytes(MAX_TOTAL_BYTES)
              + ")");
    }
    Files.createDirectories(to);
    if (tooLarge.size() > 12) {
      int more = tooLarge.size() - 10;
      List<String> cut = new ArrayList<>(tooLarge.subList(0, 10));
      cut.add("and " + more + " more");
      return new Copied(0, cut, links);
    }
    if (!tooLarge.isEmpty()) {
      return new Copied(0, tooLarge, links);
    }
    sources.sort(Comparator.naturalOrder());
    for (Path p : sources) {
      Path target = to.resolve(from.relativize(p).toString());
      Files.createDirectories(target.getParent());
      Files.copy(p, target);
    }
    return new Copied(sources.size(), List.of(), links);
  }

  /**
   * A folder name for each student, for their files in the report: their name where it is safe,
   * with anything else replaced; two students never share one (not even on a file system that
   * ignores case), and the names depend only on the set of students, so a re-grade of one finds the
   * same folder.
   */
  public static java.util.Map<String, String> reportFolders(List<String> students) {
    java.util.Map<String, String> out = new java.util.LinkedHashMap<>();
    java.util.Set<String> taken = new java.util.HashSet<>();
    List<String> sorted = new ArrayList<>(students);
    sorted.sort(Comparator.naturalOrder());
    // names that need no change first, so that 'a_b' keeps its name and 'a b' becomes 'a_b~2'
    sorted.sort(Comparator.comparing(s -> !safeName(s).equals(s)));
    for (String s : sorted) {
      String base = safeName(s);
      String name = base;
      for (int k = 2; !taken.add(name.toLowerCase(Locale.ROOT)); k++) {
        name = base + "~" + k;
      }
      out.put(s, name);
    }
    java.util.Map<String, String> ordered = new java.util.LinkedHashMap<>();
    for (String s : students) {
      ordered.put(s, out.get(s));
    }
    return ordered;
  }

  static String safeName(String s) {
    String t = s.replaceAll("[^A-Za-z0-9._-]", "_");
    return t.isEmpty() || t.equals(".") || t.equals("..") ? "_" + t.replace('.', '_') : t;
  }

  static void deleteTree(Path p) throws IOException {
    org.jaria.classroom.sandbox.Cleanup.deleteTree(p);
  }
}
