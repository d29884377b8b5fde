package org.jaria.net.server;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.jaria.net.protocol.PasswordHash;

/**
 * A user/password file (ArNetworking's {@code ArServerUserInfo}). One user per line:
 *
 * <pre>
 * # comments and blank lines are ignored
 * User operator pbkdf2-sha256:60000:&lt;salt, base64&gt;:&lt;key, base64&gt; all
 * User visitor  pbkdf2-sha256:60000:...:... RobotInfo SensorInfo
 * </pre>
 *
 * <p>The words after the key are the user's command groups ({@code all} for every group). Make a
 * line with {@link #makeLine(String, String, String...)}; the password itself is never stored. User
 * names are compared exactly.
 */
public final class ArServerUserInfo implements Authenticator {

  private static final String SCHEME = "pbkdf2-sha256";

  private final Map<String, Credentials> users;
  private final String source;

  private ArServerUserInfo(Map<String, Credentials> users, String source) {
    this.users = Map.copyOf(users);
    this.source = source;
  }

  /**
   * Reads a user file.
   *
   * @throws IOException if it cannot be read
   * @throws IllegalArgumentException naming file and line for a malformed line or a duplicate user
   */
  public static ArServerUserInfo readFile(Path file) throws IOException {
    return parse(Files.readAllLines(file, StandardCharsets.UTF_8), file.toString());
  }

  /**
   * Parses the lines of a user file.
   *
   * @param sourceName named in error messages
   * @throws IllegalArgumentException naming source and line for a malformed line
   */
  public static ArServerUserInfo parse(List<String> lines, String sourceName) {
    Map<String, Credentials> users = new LinkedHashMap<>();
    for (int i = 0; i < lines.size(); i++) {
      String line = lines.get(i).strip();
      if (line.isEmpty() || line.startsWith("#")) {
        continue;
      }
      String where = sourceName + ":" + (i + 1) + ": ";
      String[] w = line.split("\\s+");
      if (w.length < 3 || !w[0].equalsIgnoreCase("User")) {
        throw new IllegalArgumentException(
            where + "expected 'User <name> " + SCHEME + ":<iterations>:<salt>:<key> [groups...]'");
      }
      String[] k = w[2].split(":", -1);
      if (k.length != 4 || !k[0].equals(SCHEME)) {
        throw new IllegalArgumentException(
            where
                + "the key must look like "
                + SCHEME
                + ":<iterations>:<salt>:<key>; make one with ArServerUserInfo.makeLine");
      }
      int iterations;
      byte[] salt;
      byte[] key;
      try {
        iterations = Integer.parseInt(k[1]);
        salt = Base64.getDecoder().decode(k[2]);
        key = Base64.getDecoder().decode(k[3]);
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException(where + "bad number or base64 in the key", e);
      }
      if (iterations < 1 || iterations > PasswordHash.MAX_ITERATIONS) {
        throw new IllegalArgumentException(
            where + "iterations must be 1.." + PasswordHash.MAX_ITERATIONS);
      }
      if (key.length != PasswordHash.KEY_BYTES) {
        throw new IllegalArgumentException(
            where + "the key must be " + PasswordHash.KEY_BYTES + " bytes, is " + key.length);
      }
      Set<String> groups = new LinkedHashSet<>(List.of(w).subList(3, w.length));
      if (users.put(w[1], new Credentials(w[1], salt, iterations, key, groups)) != null) {
        throw new IllegalArgumentException(where + "user " + w[1] + " is listed twice");
      }
    }
    return new ArServerUserInfo(users, sourceName);
  }

  /**
   * A line for a user file, with a fresh random salt and the default number of rounds.
   *
   * @param groups command groups ({@code "all"} for every group)
   */
  public static String makeLine(String user, String password, String... groups) {
    return makeLine(user, password, PasswordHash.DEFAULT_ITERATIONS, groups);
  }

  /** As {@link #makeLine(String, String, String...)}, with {@code iterations} PBKDF2 rounds. */
  public static String makeLine(String user, String password, int iterations, String... groups) {
    if (user.isEmpty() || user.chars().anyMatch(Character::isWhitespace)) {
      throw new IllegalArgumentException("a user name must be one word, got '" + user + "'");
    }
    byte[] salt = PasswordHash.randomBytes(new SecureRandom(), PasswordHash.SALT_BYTES);
    byte[] key = PasswordHash.derive(password, salt, iterations);
    Base64.Encoder b64 = Base64.getEncoder();
    return String.format(
        Locale.ROOT,
        "User %s %s:%d:%s:%s%s",
        user,
        SCHEME,
        iterations,
        b64.encodeToString(salt),
        b64.encodeToString(key),
        groups.length == 0 ? "" : " " + String.join(" ", groups));
  }

  @Override
  public Optional<Credentials> find(String user) {
    return Optional.ofNullable(users.get(user));
  }

  /** The user names. */
  public Set<String> getUserNames() {
    return users.keySet();
  }

  @Override
  public String toString() {
    return "ArServerUserInfo[" + source + ", " + users.size() + " users]";
  }
}
