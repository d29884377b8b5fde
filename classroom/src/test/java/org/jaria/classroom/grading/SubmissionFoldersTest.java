package org.jaria.classroom.grading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The submissions folder at its edges, as a teacher found them. */
class SubmissionFoldersTest {

  private static void java(Path dir, String name) throws IOException {
    Files.createDirectories(dir);
    Files.writeString(dir.resolve(name), "class X {}");
  }

  @Test
  void aStrayFileBesideTheStudentsIsListedAndSkipped(@TempDir Path tmp) throws IOException {
    java(tmp.resolve("ana"), "Square.java");
    java(tmp.resolve("bob"), "Square.java");
    java(tmp, "Square.java");
    Files.writeString(tmp.resolve("notes.txt"), "x");
    Files.writeString(tmp.resolve(".DS_Store"), "x");
    SubmissionFolders.Scan s = SubmissionFolders.scan(tmp);
    assertEquals(
        List.of("ana", "bob"),
        s.submissions().stream().map(SubmissionFolders.Submission::student).toList());
    assertEquals(2, s.skipped().size(), s.skipped().toString());
    assertTrue(
        s.skipped().get(0).startsWith("skipped Square.java: a file beside"), s.skipped().get(0));
  }

  @Test
  void aFolderOfJavaFilesAloneIsOneStudent(@TempDir Path tmp) throws IOException {
    java(tmp.resolve("mine"), "Square.java");
    assertEquals(List.of(tmp.resolve("mine")), SubmissionFolders.submissions(tmp.resolve("mine")));
  }

  @Test
  void aLinkedStudentFolderIsReportedNotLeftOut(@TempDir Path tmp) throws IOException {
    java(tmp.resolve("elsewhere/ana"), "Square.java");
    Files.createDirectories(tmp.resolve("subs"));
    java(tmp.resolve("subs/bob"), "Square.java");
    Files.createSymbolicLink(tmp.resolve("subs/ana"), tmp.resolve("elsewhere/ana"));
    SubmissionFolders.Scan s = SubmissionFolders.scan(tmp.resolve("subs"));
    assertEquals(2, s.submissions().size());
    assertTrue(s.submissions().get(0).link(), s.submissions().toString());
  }

  @Test
  void namesThatLookAlikeKeepFoldersOfTheirOwn() {
    Map<String, String> f =
        SubmissionFolders.reportFolders(List.of("a b", "a_b", "Ana", "ana", "..", "x/y"));
    assertEquals("a_b", f.get("a_b"));
    assertEquals("a_b~2", f.get("a b"));
    assertEquals("Ana", f.get("Ana"));
    assertEquals("ana~2", f.get("ana"));
    assertEquals(
        6, f.values().stream().map(v -> v.toLowerCase(java.util.Locale.ROOT)).distinct().count());
    assertTrue(f.values().stream().noneMatch(v -> v.equals("..") || v.contains("/")), f.toString());
    // the same set of students always gets the same folders (a re-grade of one finds its own)
    assertEquals(
        f, SubmissionFolders.reportFolders(List.of("x/y", "..", "ana", "Ana", "a_b", "a b")));
  }

  @Test
  void aSubmissionOverTheLimitsIsNamedAndNothingIsCopied(@TempDir Path tmp) throws IOException {
    Path big = tmp.resolve("big");
    Files.createDirectories(big);
    try (RandomAccessFile f = new RandomAccessFile(big.resolve("Huge.java").toFile(), "rw")) {
      f.setLength(50L << 20);
    }
    java(big, "Square.java");
    SubmissionFolders.Copied c = SubmissionFolders.copySources(big, tmp.resolve("out-big"));
    assertEquals(0, c.files());
    assertTrue(
        c.tooLarge().get(0).startsWith("Huge.java is 50.0 MB (at most 1.0 MB per file)"),
        c.tooLarge().toString());
    try (var left = Files.list(tmp.resolve("out-big"))) {
      assertEquals(List.of(), left.toList());
    }

    Path many = tmp.resolve("many");
    for (int i = 0; i < 10_000; i++) {
      java(many.resolve("p" + (i / 1000)), "C" + i + ".java");
    }
    SubmissionFolders.Copied m = SubmissionFolders.copySources(many, tmp.resolve("out-many"));
    assertEquals(0, m.files());
    assertEquals("10000 .java files (at most 200)", m.tooLarge().get(0));
  }

  @Test
  void linksAndFilesDeepDownAreFoundNotDroppedSilently(@TempDir Path tmp) throws IOException {
    Path s = tmp.resolve("s");
    Path deep = s.resolve("a/b/c/d/e/f/g/h/i/j");
    java(deep, "Deep.java");
    java(tmp.resolve("other"), "Other.java");
    Files.createSymbolicLink(s.resolve("Linked.java"), tmp.resolve("other/Other.java"));
    SubmissionFolders.Copied c = SubmissionFolders.copySources(s, tmp.resolve("out"));
    assertEquals(1, c.files());
    assertTrue(Files.exists(tmp.resolve("out/a/b/c/d/e/f/g/h/i/j/Deep.java")));
    assertEquals(List.of("Linked.java"), c.links());
  }

  @Test
  void aFolderOfJavaFilesIsOneSubmission(@TempDir Path tmp) throws IOException {
    java(tmp.resolve("mine"), "Square.java");
    assertEquals(List.of(tmp.resolve("mine")), SubmissionFolders.submissions(tmp.resolve("mine")));
    assertEquals(List.of(tmp.resolve("mine")), SubmissionFolders.submissions(tmp));
  }
}
