package org.jaria.net.server;

/**
 * The longest texts a client can make the server keep or send back, so that one client cannot grow
 * what every client receives (a 31,000-character goal name in every {@code update}) or make a
 * packet overflow. ARIA reads such texts into buffers of 256 to 1024 bytes; these limits are in the
 * same range.
 */
public final class TextLimits {

  /** A name a client gives: a goal, a sensor, a camera, a mode, a parameter. */
  public static final int MAX_NAME = 256;

  /** A value a client sets (a configuration parameter, a command's argument). */
  public static final int MAX_VALUE = 1024;

  /** A message the server sends back (a refusal, a status line). */
  public static final int MAX_MESSAGE = 500;

  private TextLimits() {}

  /** {@code s} cut to at most {@code max} characters (null as ""), marked with "…" if cut. */
  public static String clip(String s, int max) {
    if (s == null) {
      return "";
    }
    return s.length() <= max ? s : s.substring(0, Math.max(0, max - 1)) + "…";
  }
}
