package org.jaria.laser;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * Hokuyo's SCIP 1.1, the protocol of ARIA's {@code ArUrg}: single-letter commands ended by a line
 * feed, each answered by its echo, a one-character status ({@code 0}: done), data lines without
 * checksums, and an empty line. Plain functions over strings.
 *
 * <ul>
 *   <li>{@code V}: the version, lines {@code VEND:}, {@code PROD:}, {@code FIRM:}, {@code PROT:},
 *       {@code SERI:} (and {@code STAT:});
 *   <li>{@code S} + 6-digit baud + 7 reserved characters: change the serial rate;
 *   <li>{@code G} + first step (3 digits) + last step (3) + cluster (2): one scan, each distance in
 *       two 6-bit characters (0..4095 mm), 64 characters a line.
 * </ul>
 */
public final class Scip11 {

  private Scip11() {}

  /** The version request. */
  public static final String VERSION = "V";

  /** The status of a command that was done. */
  public static final String OK = "0";

  /** Largest distance two characters carry, mm. */
  public static final int MAX_RANGE = 4095;

  /** The request for one scan of steps {@code first..last}, {@code cluster} steps a reading. */
  public static String distanceRequest(int first, int last, int cluster) {
    if (first < 0 || last > 999 || first > last || cluster < 1 || cluster > 99) {
      throw new IllegalArgumentException(
          "SCIP 1.1 scans steps 0..999 in order with a cluster of 1..99, not "
              + first
              + ".."
              + last
              + " by "
              + cluster);
    }
    return String.format(Locale.ROOT, "G%03d%03d%02d", first, last, cluster);
  }

  /** The request to change the serial rate to {@code baud} (the 7 reserved characters as ARIA). */
  public static String baudRequest(int baud) {
    return String.format(Locale.ROOT, "S%06d7654321", baud);
  }

  /** The status of an answer: its second line, or "" if it has none. */
  public static String status(ScipBlock b) {
    return b.lines().size() < 2 ? "" : b.lines().get(1);
  }

  /** The {@code NAME:value} lines of a V answer. */
  public static Map<String, String> info(ScipBlock b) {
    Map<String, String> m = new HashMap<>();
    for (int i = 2; i < b.lines().size(); i++) {
      String l = b.lines().get(i);
      int colon = l.indexOf(':');
      if (colon > 0) {
        m.put(l.substring(0, colon), l.substring(colon + 1));
      }
    }
    return m;
  }

  /**
   * The distances of a G answer, mm, in step order.
   *
   * @throws IllegalArgumentException if a character is outside the encoding or a value is split
   */
  public static int[] distances(ScipBlock b) {
    StringBuilder sb = new StringBuilder();
    for (int i = 2; i < b.lines().size(); i++) {
      sb.append(b.lines().get(i));
    }
    return Scip.decodeAll(sb, 2);
  }

  /** The data lines a device sends for a run of encoded distances: 64 characters each. */
  public static java.util.List<String> dataLines(CharSequence encoded) {
    java.util.List<String> lines = new java.util.ArrayList<>();
    for (int i = 0; i < encoded.length(); i += Scip.DATA_LINE) {
      lines.add(encoded.subSequence(i, Math.min(encoded.length(), i + Scip.DATA_LINE)).toString());
    }
    return lines;
  }
}
