package org.jaria.net.protocol;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import javax.crypto.Mac;
import javax.crypto.SecretKeyFactory;
import javax.crypto.spec.PBEKeySpec;
import javax.crypto.spec.SecretKeySpec;

/**
 * The login arithmetic shared by server and client. A password is never stored or sent: the server
 * keeps {@code key = PBKDF2-HMAC-SHA256(password, salt, iterations)}; at login it sends the salt,
 * the iteration count and a fresh random nonce, the client derives the same key from the password
 * and answers {@code HMAC-SHA256(key, nonce)}, which the server compares in constant time. A
 * captured login cannot be replayed (the next nonce differs).
 */
public final class PasswordHash {

  private PasswordHash() {}

  /** PBKDF2 rounds for new passwords: slow enough to make guessing a stolen file expensive. */
  public static final int DEFAULT_ITERATIONS = 60_000;

  /** Bytes of a salt. */
  public static final int SALT_BYTES = 16;

  /** Bytes of a derived key and of a proof. */
  public static final int KEY_BYTES = 32;

  /** Most PBKDF2 rounds a client accepts from a server (a hostile server could ask for more). */
  public static final int MAX_ITERATIONS = 10_000_000;

  /** The stored key of {@code password}. */
  public static byte[] derive(String password, byte[] salt, int iterations) {
    if (iterations < 1 || iterations > MAX_ITERATIONS) {
      throw new IllegalArgumentException(
          "PBKDF2 iterations must be 1.." + MAX_ITERATIONS + ", got " + iterations);
    }
    PBEKeySpec spec = new PBEKeySpec(password.toCharArray(), salt, iterations, KEY_BYTES * 8);
    try {
      return SecretKeyFactory.getInstance("PBKDF2WithHmacSHA256").generateSecret(spec).getEncoded();
    } catch (GeneralSecurityException e) {
      throw new IllegalStateException("this Java has no PBKDF2WithHmacSHA256", e);
    } finally {
      spec.clearPassword();
    }
  }

  /** The login proof for a key and the server's nonce. */
  public static byte[] proof(byte[] key, byte[] nonce) {
    try {
      Mac mac = Mac.getInstance("HmacSHA256");
      mac.init(new SecretKeySpec(key, "HmacSHA256"));
      mac.update(Protocol.MAGIC.getBytes(StandardCharsets.US_ASCII));
      return mac.doFinal(nonce);
    } catch (GeneralSecurityException e) {
      throw new IllegalStateException("this Java has no HmacSHA256", e);
    }
  }

  /** Compares two proofs in time independent of where they differ. */
  public static boolean matches(byte[] expected, byte[] given) {
    return given != null && MessageDigest.isEqual(expected, given);
  }

  /** {@code n} random bytes. */
  public static byte[] randomBytes(SecureRandom random, int n) {
    byte[] b = new byte[n];
    random.nextBytes(b);
    return b;
  }
}
