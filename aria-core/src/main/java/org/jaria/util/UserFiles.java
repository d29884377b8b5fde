package org.jaria.util;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Why a file that someone named on a command line or in a dialog cannot be read, said the way a
 * person can act on: there is no such file, it is a folder, or they may not read it.
 */
public final class UserFiles {

  private UserFiles() {}

  /**
   * What is wrong with reading {@code typed} as a file, and what to do; empty if it is a readable
   * regular file.
   */
  public static Optional<String> problem(String typed) {
    Path p;
    try {
      p = Path.of(typed);
    } catch (InvalidPathException e) {
      return Optional.of("'" + typed + "' is not a file name (" + e.getReason() + ")");
    }
    return problem(p);
  }

  /** {@link #problem(String)} for a path. */
  public static Optional<String> problem(Path file) {
    Path abs = file.toAbsolutePath().normalize();
    if (Files.isDirectory(file)) {
      return Optional.of(abs + " is a folder, not a file: name a file in it");
    }
    if (!Files.exists(file)) {
      return Optional.of(
          "there is no file "
              + abs
              + ": check the name, and the folder you run from (relative names start there)");
    }
    if (!Files.isReadable(file)) {
      return Optional.of(
          "you may not read "
              + abs
              + ": check its permissions (ls -l) or copy it somewhere you may read it");
    }
    return Optional.empty();
  }
}
