package org.jaria.net.server;

import java.util.Optional;
import java.util.Set;

/**
 * Who may log in: finds a user's {@link Credentials}. {@link #open()} lets anybody in (the server
 * then ignores the login digest, as an ArNetworking server without a user file does); {@link
 * ArServerUserInfo} reads ArNetworking's user file.
 */
public interface Authenticator {

  /** The user's credentials, if the user exists. */
  Optional<Credentials> find(String user);

  /** Whether anybody may log in without a password. */
  default boolean isOpen() {
    return false;
  }

  /** Anybody may log in, with every group. */
  static Authenticator open() {
    return new Authenticator() {
      @Override
      public Optional<Credentials> find(String user) {
        return Optional.of(new Credentials(user, "", Set.of("all")));
      }

      @Override
      public boolean isOpen() {
        return true;
      }
    };
  }

  /**
   * Any user name with this one password may log in, with every group.
   *
   * @throws IllegalArgumentException if the secret is empty
   */
  static Authenticator sharedSecret(String secret) {
    if (secret == null || secret.isEmpty()) {
      throw new IllegalArgumentException("a shared secret must not be empty; use open() instead");
    }
    return user -> Optional.of(new Credentials(user, secret, Set.of("all")));
  }
}
