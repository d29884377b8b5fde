package org.jaria.net.server;

import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * A user the server knows: name, password and command groups. ArNetworking's login needs the server
 * to know the password itself (it checks an MD5 digest the client made of it), so unlike a modern
 * login the password must be kept; protect the file it comes from (see {@link ArServerUserInfo}).
 * Group names are compared ignoring case, as ArNetworking does.
 */
public final class Credentials {

  private final String user;
  private final String password;
  private final Set<String> groups;

  /**
   * A user.
   *
   * @param groups command groups ({@code "all"} for every group)
   */
  public Credentials(String user, String password, Set<String> groups) {
    this.user = user;
    this.password = password;
    Set<String> g = new TreeSet<>(String.CASE_INSENSITIVE_ORDER);
    g.addAll(groups);
    this.groups = g;
  }

  /** The user name. */
  public String getUser() {
    return user;
  }

  /** The password (needed to check ArNetworking's login digest). */
  String getPassword() {
    return password;
  }

  /** The command groups, in lower case. */
  public Set<String> getGroups() {
    Set<String> s = new TreeSet<>();
    for (String g : groups) {
      s.add(g.toLowerCase(Locale.ROOT));
    }
    return s;
  }

  /** Whether data of {@code commandGroup} may be used ("" is open to everybody). */
  public boolean hasGroupAccess(String commandGroup) {
    return commandGroup == null
        || commandGroup.isEmpty()
        || groups.contains("all")
        || groups.contains(commandGroup);
  }

  @Override
  public String toString() {
    return "Credentials[" + user + ", groups " + getGroups() + "]";
  }
}
