package org.jaria.net.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Locale;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;

/**
 * Where the maps a client may switch the server to come from (ARIA's {@code Files/Map} parameter):
 * JAria's bundled maps by name ("office", "hall.map"), and the {@code .map} files of one folder. A
 * name is taken relative to the folder; absolute paths, {@code ..} leading outside, links out of
 * it, anything that is not a regular file and files over {@link #MAX_BYTES} are refused before a
 * byte is read, so a client cannot make the server read a file elsewhere. Refusals say which rule
 * was broken, never what a file holds.
 */
public final class MapFolder {

  /** Largest map file read. */
  public static final long MAX_BYTES = 64L << 20;

  private final Path folder;

  /**
   * Maps from {@code folder} and the bundled ones; null: the bundled ones only.
   *
   * @throws IOException if the folder does not exist
   */
  public MapFolder(Path folder) throws IOException {
    this.folder = folder == null ? null : folder.toRealPath();
    if (this.folder != null && !Files.isDirectory(this.folder)) {
      throw new IOException(folder + " is not a folder: give the folder the maps are in");
    }
  }

  /** The folder (null: bundled maps only). */
  public Path getFolder() {
    return folder;
  }

  /**
   * Loads map {@code name}: a file of the folder, or else a bundled map.
   *
   * @throws IllegalArgumentException if the name breaks a rule or names no map (the message says
   *     which)
   * @throws IOException if the file cannot be read
   * @throws MapFormatException if it is not a valid map
   */
  public ArMap load(String name) throws IOException, MapFormatException {
    if (name == null || name.isBlank()) {
      throw new IllegalArgumentException("give the name of a map file");
    }
    if (name.length() > TextLimits.MAX_NAME || name.indexOf('\0') >= 0) {
      throw new IllegalArgumentException("not a map file name");
    }
    Path file = inFolder(name);
    if (file != null) {
      return ArMap.readFile(file);
    }
    String bundled = name.toLowerCase(Locale.ROOT).replaceFirst("\\.map$", "");
    if (ArMap.BUNDLED_MAPS.contains(bundled)) {
      return ArMap.loadBundled(bundled);
    }
    throw new IllegalArgumentException(
        "no map '"
            + name
            + "'"
            + (folder == null
                ? ": this server offers only its bundled maps " + ArMap.BUNDLED_MAPS
                : " in the server's map folder nor among the bundled maps"));
  }

  /** The file {@code name} of the folder, null if there is none, refused if out of bounds. */
  private Path inFolder(String name) throws IOException {
    if (folder == null) {
      return null;
    }
    Path given;
    try {
      given = Path.of(name);
    } catch (java.nio.file.InvalidPathException e) {
      throw new IllegalArgumentException("not a map file name");
    }
    if (given.isAbsolute()) {
      throw new IllegalArgumentException("a map is named relative to the server's map folder");
    }
    Path file = folder.resolve(given).normalize();
    if (!file.startsWith(folder)) {
      throw new IllegalArgumentException("a map must be inside the server's map folder");
    }
    if (!Files.exists(file, LinkOption.NOFOLLOW_LINKS)) {
      return null;
    }
    Path real = file.toRealPath();
    if (!real.startsWith(folder)) {
      throw new IllegalArgumentException("a map must be inside the server's map folder");
    }
    if (!Files.isRegularFile(real)) {
      throw new IllegalArgumentException("'" + name + "' is not a file");
    }
    if (Files.size(real) > MAX_BYTES) {
      throw new IllegalArgumentException(
          "'" + name + "' is larger than " + (MAX_BYTES >> 20) + " MiB");
    }
    return real;
  }
}
