package org.jaria.laser;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * One SCIP 2.0 answer: the echoed command, a status line, then data lines, ended by an empty line.
 * Lines are stored without their line feeds and with their checksums still on.
 *
 * @param lines the lines, echo first
 */
public record ScipBlock(List<String> lines) {

  /** Copies. */
  public ScipBlock {
    lines = List.copyOf(lines);
  }

  /** The echoed command (e.g. "MD0044072501000"). */
  public String echo() {
    return lines.isEmpty() ? "" : lines.get(0);
  }

  /** The two status characters, or "" if the block has no (valid) status line. */
  public String status() {
    if (lines.size() < 2) {
      return "";
    }
    String s = lines.get(1);
    // SCIP 2.0 status lines are two characters and a checksum; some devices omit the checksum.
    if (s.length() == 3 && Scip.checksum(s, 0, 2) == s.charAt(2)) {
      return s.substring(0, 2);
    }
    return s.length() == 2 ? s : "";
  }

  /**
   * The {@code NAME:value} pairs of a VV/PP/II answer (lines after the status).
   *
   * @throws IllegalArgumentException if a line's checksum does not match
   */
  public Map<String, String> info() {
    Map<String, String> m = new HashMap<>();
    for (int i = 2; i < lines.size(); i++) {
      String l = lines.get(i);
      int colon = l.indexOf(':');
      int semi = l.lastIndexOf(';');
      if (colon < 0 || semi < colon) {
        continue;
      }
      if (semi + 1 < l.length() && Scip.checksum(l, 0, semi) != l.charAt(semi + 1)) {
        throw new IllegalArgumentException("bad checksum on '" + l + "'");
      }
      m.put(l.substring(0, colon), l.substring(colon + 1, semi));
    }
    return m;
  }

  /**
   * The data of a distance answer: lines from {@code first} on, each stripped of its checksum after
   * checking it, joined.
   *
   * @throws IllegalArgumentException if a line's checksum does not match
   */
  public String joinedData(int first) {
    StringBuilder sb = new StringBuilder();
    for (int i = first; i < lines.size(); i++) {
      String l = lines.get(i);
      if (l.isEmpty()) {
        throw new IllegalArgumentException("empty data line " + i);
      }
      int end = l.length() - 1;
      if (Scip.checksum(l, 0, end) != l.charAt(end)) {
        throw new IllegalArgumentException("bad checksum on data line " + i);
      }
      sb.append(l, 0, end);
    }
    return sb.toString();
  }
}
