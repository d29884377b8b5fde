package org.jaria.classroom.sandbox;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Counting a scratch folder's files and folders against the limit. */
class ScratchFilesTest {

  @Test
  void filesAndFoldersAtAnyDepthCountButNotTheFolderItself(@TempDir Path dir) throws IOException {
    Files.createDirectories(dir.resolve("a/b"));
    Files.writeString(dir.resolve("a/b/one.txt"), "1");
    Files.writeString(dir.resolve("two.txt"), "2");
    // a, a/b, a/b/one.txt, two.txt
    assertFalse(ScratchFiles.over(dir, 4));
    assertTrue(ScratchFiles.over(dir, 3));
    assertFalse(ScratchFiles.over(dir.resolve("a/b"), 1));
  }
}
