package org.jaria.map;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import org.jaria.util.UserFiles;

/**
 * A map as a person names it on a command line or in a dialog: the path of a {@code .map} file, or
 * the name of one of JAria's bundled maps ({@link ArMap#BUNDLED_MAPS}, with or without {@code
 * .map}). A file that exists wins over a bundled map of the same name. Every command that takes a
 * map resolves it here, so each says the same thing when the name leads nowhere.
 */
public final class MapNames {

  private MapNames() {}

  /**
   * The bundled map {@code typed} names ("hall", "hall.map", "Hall"), or null when it names a file
   * that exists or no bundled map.
   */
  public static String bundledName(String typed) {
    if (exists(typed)) {
      return null;
    }
    String name = typed.toLowerCase(Locale.ROOT);
    name = name.endsWith(".map") ? name.substring(0, name.length() - 4) : name;
    return ArMap.BUNDLED_MAPS.contains(name) ? name : null;
  }

  /**
   * Why {@code typed} names no map that can be read, what to do about it, and which maps are
   * bundled; empty when it names a bundled map or a readable file (whose content may still not be a
   * map: reading it says so).
   */
  public static Optional<String> problem(String typed) {
    if (bundledName(typed) != null) {
      return Optional.empty();
    }
    String bundled = "bundled: " + String.join(", ", ArMap.BUNDLED_MAPS);
    if (!exists(typed)) {
      String name = typed.replaceAll("(?i)\\.map$", "");
      boolean path = typed.contains("/") || typed.contains("\\");
      return Optional.of(
          "there is no map file "
              + absolute(typed)
              + (path
                  ? ": check the path, or give a bundled map's name ("
                  : " and no bundled map named '"
                      + name
                      + "': give a .map file's path or a bundled map's name (")
              + bundled
              + ")");
    }
    return UserFiles.problem(typed).map(why -> why + " (or a bundled map's name; " + bundled + ")");
  }

  private static boolean exists(String typed) {
    try {
      return Files.exists(Path.of(typed));
    } catch (InvalidPathException e) {
      return false;
    }
  }

  private static String absolute(String typed) {
    try {
      return Path.of(typed).toAbsolutePath().normalize().toString();
    } catch (InvalidPathException e) {
      return "'" + typed + "'";
    }
  }
}
