package org.jaria.net.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Where a scan log a client asks for is written: the rule of ArNetworking's {@code mappingStart}
 * (the name in lower case, {@code .2d} added unless it ends so) confined to the server's map
 * folder. A name is a plain file name of that folder: no folders in it, no leading dot (so no
 * {@code ..} and no hidden files), no control characters; an existing file of that name must be a
 * regular file, not a link (which could lead out of the folder) nor a device or pipe. Refusals say
 * which rule was broken, never what is on the disk beyond it.
 */
public final class ScanLogName {

  /** The scan log's extension, as ARIA's mapping server adds it. */
  public static final String EXTENSION = ".2d";

  private ScanLogName() {}

  /**
   * The log's name as ARIA's server makes it from what a client sent: lower case, {@code .2d} added
   * unless it ends with it.
   */
  public static String fileName(String requested) {
    String lower = requested.toLowerCase(Locale.ROOT);
    return lower.endsWith(EXTENSION) ? lower : lower + EXTENSION;
  }

  /**
   * The file in {@code folder} that a request for {@code requested} writes.
   *
   * @throws IllegalArgumentException if the name breaks a rule (the message says which, for the
   *     client)
   * @throws IOException if the folder cannot be read
   */
  public static Path resolve(Path folder, String requested) throws IOException {
    if (requested == null || requested.isBlank()) {
      throw new IllegalArgumentException("give the scan a file name, e.g. lab");
    }
    if (requested.length() > TextLimits.MAX_NAME) {
      throw new IllegalArgumentException(
          "a scan's file name has at most " + TextLimits.MAX_NAME + " characters");
    }
    for (int i = 0; i < requested.length(); i++) {
      char c = requested.charAt(i);
      if (c < 0x20 || c == 0x7F) {
        throw new IllegalArgumentException("a scan's file name has no control characters");
      }
      if (c == '/' || c == '\\' || c == ':') {
        throw new IllegalArgumentException(
            "a scan is a file of the server's map folder: give a file name without folders");
      }
    }
    if (requested.startsWith(".")) {
      throw new IllegalArgumentException("a scan's file name does not start with a dot");
    }
    String name = fileName(requested.strip());
    if (!name.equals(fileName(requested))) {
      throw new IllegalArgumentException("a scan's file name does not start or end with spaces");
    }
    Path real = folder.toRealPath();
    Path file = real.resolve(name);
    if (!file.getParent().equals(real)) {
      throw new IllegalArgumentException("a scan is a file of the server's map folder");
    }
    if (Files.isSymbolicLink(file)) {
      throw new IllegalArgumentException("'" + name + "' is a link: give another name");
    }
    if (Files.exists(file, LinkOption.NOFOLLOW_LINKS)
        && !Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
      throw new IllegalArgumentException("'" + name + "' is not a file: give another name");
    }
    return file;
  }

  /**
   * The map a log is built into: {@code lab.2d} gives {@code lab.map}, or {@code lab-2.map}, {@code
   * lab-3.map} ... if that exists already (a scan never replaces a map of the folder).
   */
  public static Path mapFor(Path log) {
    String n = log.getFileName().toString();
    String base = n.endsWith(EXTENSION) ? n.substring(0, n.length() - EXTENSION.length()) : n;
    Path dir = log.getParent();
    Path candidate = dir.resolve(base + ".map");
    for (int i = 2; Files.exists(candidate, LinkOption.NOFOLLOW_LINKS); i++) {
      candidate = dir.resolve(base + "-" + i + ".map");
    }
    return candidate;
  }
}
