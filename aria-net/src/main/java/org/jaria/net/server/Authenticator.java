package org.jaria.net.server;

import java.security.SecureRandom;
import java.util.Optional;
import java.util.Set;
import org.jaria.net.protocol.PasswordHash;

/**
 * Who may log in to an {@link ArServerBase}. Three kinds:
 *
 * <ul>
 *   <li>{@link #open()}: anybody (the server then listens on the loopback interface only, unless
 *       told otherwise);
 *   <li>{@link #sharedSecret(String)}: any user name with one password known to all operators;
 *   <li>{@link ArServerUserInfo}: a user/password file with salted keys and command groups, as
 *       ArNetworking's user info file.
 * </ul>
 */
public interface Authenticator {

  /** The credentials of {@code user}, or empty if there is no such user. */
  Optional<Credentials> find(String user);

  /** Whether anybody may log in without a password. */
  default boolean isOpen() {
    return false;
  }

  /** An authenticator that lets everybody in, with access to every command group. */
  static Authenticator open() {
    return new Authenticator() {
      @Override
      public Optional<Credentials> find(String user) {
        return Optional.of(new Credentials(user, new byte[0], 0, new byte[0], Set.of("all")));
      }

      @Override
      public boolean isOpen() {
        return true;
      }
    };
  }

  /**
   * An authenticator that accepts any user name with the password {@code secret}, with access to
   * every command group.
   */
  static Authenticator sharedSecret(String secret) {
    if (secret == null || secret.isEmpty()) {
      throw new IllegalArgumentException("a shared secret must not be empty; use open() instead");
    }
    byte[] salt = PasswordHash.randomBytes(new SecureRandom(), PasswordHash.SALT_BYTES);
    byte[] key = PasswordHash.derive(secret, salt, PasswordHash.DEFAULT_ITERATIONS);
    return user ->
        Optional.of(
            new Credentials(user, salt, PasswordHash.DEFAULT_ITERATIONS, key, Set.of("all")));
  }
}
