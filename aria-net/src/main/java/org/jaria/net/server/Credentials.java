package org.jaria.net.server;

import java.util.Arrays;
import java.util.Set;

/**
 * What the server knows about one user: the salted password key (never the password) and the
 * command groups the user may use ({@code "all"} for every group).
 */
public final class Credentials {

  private final String user;
  private final byte[] salt;
  private final int iterations;
  private final byte[] key;
  private final Set<String> groups;

  /**
   * Credentials.
   *
   * @param user the user name
   * @param salt the PBKDF2 salt
   * @param iterations the PBKDF2 rounds
   * @param key {@code PBKDF2-HMAC-SHA256(password, salt, iterations)}
   * @param groups the command groups allowed
   */
  public Credentials(String user, byte[] salt, int iterations, byte[] key, Set<String> groups) {
    this.user = user;
    this.salt = salt.clone();
    this.iterations = iterations;
    this.key = key.clone();
    this.groups = Set.copyOf(groups);
  }

  /** The user name. */
  public String getUser() {
    return user;
  }

  /** The salt (a copy). */
  public byte[] getSalt() {
    return salt.clone();
  }

  /** The PBKDF2 rounds. */
  public int getIterations() {
    return iterations;
  }

  /** The derived key (a copy). */
  public byte[] getKey() {
    return key.clone();
  }

  /** The command groups allowed. */
  public Set<String> getGroups() {
    return groups;
  }

  /** Whether the user may use data of {@code commandGroup} (empty group: anybody). */
  public boolean hasGroupAccess(String commandGroup) {
    return commandGroup == null
        || commandGroup.isEmpty()
        || groups.contains("all")
        || groups.contains(commandGroup);
  }

  @Override
  public String toString() {
    return "Credentials[" + user + ", groups " + groups + ", key " + Arrays.hashCode(key) + "]";
  }
}
