package org.jaria.net.server;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * ArNetworking's user file ({@code ArServerUserInfo}), the format ARIA's {@code
 * serverDemo.userInfo} uses:
 *
 * <pre>
 * UserInfoVersion1
 * ; comments start with ';' (or '#')
 * user operator secret1 all
 * user visitor  secret2 RobotInfo SensorInfo
 * </pre>
 *
 * <p>After the header line each {@code user} line has a name, a password (letters and digits only,
 * as ARIA requires) and the user's command groups ({@code all} for every group). Names and groups
 * are compared ignoring case. The passwords are stored as written, because ArNetworking's login
 * checks a digest made from the password itself: {@link #readFile} therefore refuses a file that
 * other users of the computer may read.
 */
public final class ArServerUserInfo implements Authenticator {

  private final Map<String, Credentials> users;
  private final String source;

  private ArServerUserInfo(Map<String, Credentials> users, String source) {
    this.users = users;
    this.source = source;
  }

  /**
   * Reads a user file.
   *
   * @throws IOException if it cannot be read, or if users other than its owner may read it
   * @throws IllegalArgumentException naming file and line for a malformed line or a duplicate user
   */
  public static ArServerUserInfo readFile(Path file) throws IOException {
    checkPrivate(file);
    return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.toString());
  }

  /**
   * Refuses a password file that its group or others may read.
   *
   * @throws IOException saying what to run to fix it
   */
  public static void checkPrivate(Path file) throws IOException {
    Set<PosixFilePermission> p;
    try {
      p = Files.getPosixFilePermissions(file);
    } catch (UnsupportedOperationException e) {
      return; // Not a POSIX file system: nothing to check.
    }
    if (p.contains(PosixFilePermission.GROUP_READ) || p.contains(PosixFilePermission.OTHERS_READ)) {
      throw new IOException(
          file
              + " holds passwords but other users may read it; run 'chmod 600 "
              + file
              + "' and start again");
    }
  }

  /**
   * Parses the lines of a user file.
   *
   * @param sourceName named in error messages
   * @throws IllegalArgumentException naming source and line for a malformed line
   */
  public static ArServerUserInfo parse(List<String> lines, String sourceName) {
    Map<String, Credentials> users = new TreeMap<>(String.CASE_INSENSITIVE_ORDER);
    boolean header = false;
    for (int i = 0; i < lines.size(); i++) {
      String line = lines.get(i).strip();
      if (line.isEmpty() || line.startsWith(";") || line.startsWith("#")) {
        continue;
      }
      String where = sourceName + ":" + (i + 1) + ": ";
      String[] w = line.split("\\s+");
      if (!header) {
        if (!w[0].equalsIgnoreCase("UserInfoVersion1")) {
          throw new IllegalArgumentException(where + "the first line must be 'UserInfoVersion1'");
        }
        header = true;
        continue;
      }
      if (w[0].equalsIgnoreCase("doNotUse")) {
        continue;
      }
      if (w.length < 3 || !w[0].equalsIgnoreCase("user")) {
        throw new IllegalArgumentException(where + "expected 'user <name> <password> [groups...]'");
      }
      if (!alnum(w[1]) || !alnum(w[2])) {
        throw new IllegalArgumentException(
            where + "user names and passwords may hold only letters and digits (as in ARIA)");
      }
      Set<String> groups = new LinkedHashSet<>(List.of(w).subList(3, w.length));
      if (users.put(w[1], new Credentials(w[1], w[2], groups)) != null) {
        throw new IllegalArgumentException(where + "user " + w[1] + " is listed twice");
      }
    }
    if (!header) {
      throw new IllegalArgumentException(sourceName + ": no 'UserInfoVersion1' header line");
    }
    return new ArServerUserInfo(users, sourceName);
  }

  private static boolean alnum(String s) {
    return !s.isEmpty() && s.chars().allMatch(ch -> ch < 128 && Character.isLetterOrDigit(ch));
  }

  /**
   * A line for a user file.
   *
   * @param groups command groups ({@code "all"} for every group)
   */
  public static String makeLine(String user, String password, String... groups) {
    if (!alnum(user) || !alnum(password)) {
      throw new IllegalArgumentException(
          "user names and passwords may hold only letters and digits (as in ARIA)");
    }
    return String.format(
        Locale.ROOT,
        "user %s %s%s",
        user,
        password,
        groups.length == 0 ? "" : " " + String.join(" ", groups));
  }

  @Override
  public Optional<Credentials> find(String user) {
    return Optional.ofNullable(users.get(user));
  }

  /** The user names. */
  public Set<String> getUserNames() {
    return Set.copyOf(users.keySet());
  }

  @Override
  public String toString() {
    return "ArServerUserInfo[" + source + ", " + users.size() + " users]";
  }
}
