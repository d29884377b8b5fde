package org.jaria.apps.mapper;

import java.nio.file.Path;
import java.util.Optional;
import org.jaria.map.MapNames;

/**
 * What {@code jaria mapper NAME} opens: a {@code .map} file, or one of JAria's bundled maps by name
 * ({@code columbia}, {@code office}, {@code hall}; {@code columbia.map} works too when no such file
 * is in the current folder).
 *
 * @param file the file to open, or null for a bundled map
 * @param bundledName the bundled map's name, or null for a file
 */
public record MapSource(Path file, String bundledName) {

  /** A map file. */
  public static MapSource file(Path file) {
    return new MapSource(file, null);
  }

  /**
   * Resolves what a user typed: an existing file wins; else a bundled map's name (with or without
   * {@code .map}), as {@link MapNames} decides for every command.
   *
   * @throws IllegalArgumentException if it is neither (or a folder, or unreadable), with a message
   *     that says what is wrong, what to do and which maps are bundled
   */
  public static MapSource resolve(String typed) {
    String bundled = MapNames.bundledName(typed);
    if (bundled != null) {
      return new MapSource(null, bundled);
    }
    Optional<String> problem = MapNames.problem(typed);
    if (problem.isPresent()) {
      throw new IllegalArgumentException(problem.get());
    }
    return file(Path.of(typed));
  }
}
