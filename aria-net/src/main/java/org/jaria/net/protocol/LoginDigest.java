package org.jaria.net.protocol;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;

/**
 * ArNetworking's login proof: the client sends MD5(server key + password key + password), where the
 * server key is a secret both sides were configured with (often empty) and the password key is a
 * random text the server makes for each connection. The password itself never crosses the wire, but
 * MD5 over a plain connection is weak: anyone who sees the exchange can try passwords offline. See
 * {@code aria-net/PROTOCOL.md} §4.
 */
public final class LoginDigest {

  private LoginDigest() {}

  /** Bytes of the digest. */
  public static final int DIGEST_BYTES = 16;

  /** The digest a client sends for {@code password}. */
  public static byte[] digest(String serverKey, String passwordKey, String password) {
    try {
      MessageDigest md = MessageDigest.getInstance("MD5");
      md.update(serverKey.getBytes(StandardCharsets.UTF_8));
      md.update(passwordKey.getBytes(StandardCharsets.UTF_8));
      md.update(password.getBytes(StandardCharsets.UTF_8));
      return md.digest();
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException("this Java has no MD5, which every Java must have", e);
    }
  }

  /** Compares two digests in time that does not depend on where they differ. */
  public static boolean matches(byte[] expected, byte[] got) {
    return MessageDigest.isEqual(expected, got);
  }

  /**
   * A fresh password key: like ARIA's, 0 to 99 characters between '0' and 'z'; unlike ARIA's, from
   * a cryptographic random source and at least 16 characters long.
   */
  public static String newPasswordKey(SecureRandom random) {
    int n = 16 + random.nextInt(84);
    StringBuilder sb = new StringBuilder(n);
    for (int i = 0; i < n; i++) {
      sb.append((char) ('0' + random.nextInt('z' - '0')));
    }
    return sb.toString();
  }
}
