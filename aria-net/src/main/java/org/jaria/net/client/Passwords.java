package org.jaria.net.client;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.jaria.net.server.ArServerUserInfo;

/**
 * Where a network password comes from: {@code --password-file FILE} (first line; the file must not
 * be readable by others), the environment variable {@link #ENV}, or {@code --password} (visible in
 * the process list, so the last resort). Plain functions over values, tested as such.
 */
public final class Passwords {

  private Passwords() {}

  /** The environment variable read when no password option is given. */
  public static final String ENV = "JARIA_NET_PASSWORD";

  /**
   * The password to use, or null for none.
   *
   * @param option {@code --password}, or null
   * @param file {@code --password-file}, or null
   * @param env the environment (System.getenv() in a program)
   * @throws IllegalArgumentException if both options are given
   * @throws IOException if the file cannot be read or others may read it
   */
  public static String resolve(String option, Path file, Map<String, String> env)
      throws IOException {
    if (option != null && file != null) {
      throw new IllegalArgumentException("give --password or --password-file, not both");
    }
    if (file != null) {
      ArServerUserInfo.checkPrivate(file);
      String text = Files.readString(file, StandardCharsets.UTF_8);
      int nl = text.indexOf('\n');
      String first = (nl < 0 ? text : text.substring(0, nl)).strip();
      if (first.isEmpty()) {
        throw new IllegalArgumentException(file + " is empty: put the password on its first line");
      }
      return first;
    }
    if (option != null) {
      return option;
    }
    String e = env.get(ENV);
    return e == null || e.isEmpty() ? null : e;
  }
}
