package org.jaria.classroom.sandbox;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * Counts what a student's scratch folder holds. The operating system limits the size of each file
 * the student's JVM writes but neither how many it makes nor how much they hold together, so the
 * grader counts them while the JVM runs and once more when it has ended.
 */
public final class ScratchFiles {

  private ScratchFiles() {}

  /**
   * Whether {@code dir} holds more than {@code max} files and folders (links and other entries
   * included; the folder itself not). Stops counting as soon as it is over, so a folder with a
   * million files costs no more than one with {@code max + 1}. A folder it may not read counts as
   * one entry.
   *
   * @throws IOException if {@code dir} itself cannot be read
   */
  public static boolean over(Path dir, int max) throws IOException {
    return over(dir, max, Long.MAX_VALUE);
  }

  /**
   * Whether {@code dir} holds more than {@code maxEntries} files and folders, or files of more than
   * {@code maxBytes} bytes together. Stops as soon as either is over.
   *
   * @throws IOException if {@code dir} itself cannot be read
   */
  public static boolean over(Path dir, int maxEntries, long maxBytes) throws IOException {
    long[] n = {0, 0};
    Files.walkFileTree(
        dir,
        new SimpleFileVisitor<>() {
          @Override
          public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes a) {
            return count(d, 0);
          }

          @Override
          public FileVisitResult visitFile(Path f, BasicFileAttributes a) {
            return count(f, a.isRegularFile() ? a.size() : 0);
          }

          @Override
          public FileVisitResult visitFileFailed(Path f, IOException e) {
            return count(f, 0);
          }

          private FileVisitResult count(Path p, long bytes) {
            if (!p.equals(dir)) {
              n[0]++;
            }
            n[1] += bytes;
            return n[0] > maxEntries || n[1] > maxBytes
                ? FileVisitResult.TERMINATE
                : FileVisitResult.CONTINUE;
          }
        });
    return n[0] > maxEntries || n[1] > maxBytes;
  }
}
