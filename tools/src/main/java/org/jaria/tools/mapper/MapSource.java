package org.jaria.tools.mapper;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.jaria.map.ArMap;

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
   * {@code .map}).
   *
   * @throws IllegalArgumentException if it is neither, with a message that says what exists
   */
  public static MapSource resolve(String typed) {
    Path p = Path.of(typed);
    if (Files.exists(p)) {
      return file(p);
    }
    String name =
        typed.toLowerCase(Locale.ROOT).endsWith(".map")
            ? typed.substring(0, typed.length() - 4)
            : typed;
    if (ArMap.BUNDLED_MAPS.contains(name)) {
      return new MapSource(null, name);
    }
    throw new IllegalArgumentException(
        "there is no map file "
            + p.toAbsolutePath().normalize()
            + " and no bundled map named '"
            + name
            + "' (bundled: "
            + String.join(", ", ArMap.BUNDLED_MAPS)
            + ")");
  }
}
