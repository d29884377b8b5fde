package org.jaria.ptz;

import java.nio.charset.StandardCharsets;

/**
 * Directed Perception PTU commands: ASCII letters, a signed decimal number where the command takes
 * one, and a space as delimiter (e.g. {@code "PP195 "}: pan to position 195).
 */
public final class DpptuText {

  private DpptuText() {}

  /** A command with a number: {@code letters}, {@code value}, space. */
  public static byte[] command(String letters, int value) {
    return (letters + value + " ").getBytes(StandardCharsets.US_ASCII);
  }

  /** A command without a number. */
  public static byte[] command(String letters) {
    return (letters + " ").getBytes(StandardCharsets.US_ASCII);
  }
}
