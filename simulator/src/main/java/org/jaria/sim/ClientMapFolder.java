package org.jaria.sim;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * The folder client programs may load maps from (MobileSim's {@code --cwd}), and the checks a
 * requested name passes before a byte of it is read: relative, inside the folder after {@code ..}
 * and symbolic links are resolved, a regular file (never a device or a FIFO), no larger than the
 * limit. Every refusal is a {@link Refused} whose message names the rule, never file contents.
 *
 * @param root the folder, absolute and normalized
 * @param maxBytes the largest file accepted
 */
record ClientMapFolder(Path root, long maxBytes) {

  /** A request that breaks one of the rules. */
  static final class Refused extends IOException {
    private static final long serialVersionUID = 1L;

    Refused(String why) {
      super(why);
    }
  }

  ClientMapFolder {
    root = root.toAbsolutePath().normalize();
  }

  /**
   * The file {@code requested} names inside the folder, by the names alone (no file is touched).
   *
   * @throws Refused if it is empty, absolute, not a path, or outside the folder
   */
  Path resolve(String requested) throws Refused {
    if (requested == null || requested.isBlank()) {
      throw new Refused("no file name given");
    }
    Path p;
    try {
      p = Path.of(requested);
    } catch (InvalidPathException e) {
      throw new Refused("not a valid file name");
    }
    if (p.isAbsolute() || requested.startsWith("/") || requested.startsWith("\\")) {
      throw new Refused("absolute paths are refused; name a map inside the map folder");
    }
    Path full = root.resolve(p).normalize();
    if (!full.startsWith(root)) {
      throw new Refused("outside the map folder");
    }
    return full;
  }

  /**
   * Reads the file {@code requested} names, after every check, at most {@link #maxBytes} bytes.
   *
   * @throws Refused if a rule is broken (outside through a link, not a regular file, too large)
   * @throws IOException if it does not exist or cannot be read
   */
  byte[] read(String requested) throws IOException {
    Path file = resolve(requested);
    Path real = file.toRealPath();
    if (!real.startsWith(root.toRealPath())) {
      throw new Refused("outside the map folder (through a link)");
    }
    BasicFileAttributes a =
        Files.readAttributes(real, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
    if (!a.isRegularFile()) {
      throw new Refused("not a regular file");
    }
    if (a.size() > maxBytes) {
      throw new Refused("larger than the limit of " + maxBytes + " bytes");
    }
    try (InputStream in = Files.newInputStream(real, LinkOption.NOFOLLOW_LINKS)) {
      byte[] bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
      if (bytes.length > maxBytes) {
        throw new Refused("larger than the limit of " + maxBytes + " bytes");
      }
      return bytes;
    }
  }

  /** {@code s} fit for one log line: control characters replaced, at most 120 characters. */
  static String printable(String s) {
    StringBuilder b = new StringBuilder();
    for (int i = 0; i < s.length() && b.length() < 120; i++) {
      char c = s.charAt(i);
      b.append(c < 0x20 || c == 0x7F ? '?' : c);
    }
    return b.toString();
  }
}
