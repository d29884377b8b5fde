package org.jaria.laser;

import java.util.ArrayList;
import java.util.List;

/**
 * Hokuyo's SCIP 2.0 text encoding: numbers as 2, 3 or 4 characters of 6 bits each (the value plus
 * 0x30, most significant first), and a one-character checksum per line (the low 6 bits of the sum
 * of the line's characters, plus 0x30). Plain functions over strings.
 */
public final class Scip {

  private Scip() {}

  /** Characters per line of distance data, before the checksum. */
  public static final int DATA_LINE = 64;

  /** The checksum character of {@code s} (all of it). */
  public static char checksum(CharSequence s) {
    return checksum(s, 0, s.length());
  }

  /** The checksum character of {@code s[from, to)}. */
  public static char checksum(CharSequence s, int from, int to) {
    int sum = 0;
    for (int i = from; i < to; i++) {
      sum += s.charAt(i);
    }
    return (char) ((sum & 0x3f) + 0x30);
  }

  /** Encodes {@code value} in {@code chars} characters (2: up to 4095, 3: up to 262143). */
  public static String encode(int value, int chars) {
    if (value < 0 || value >= 1 << (6 * chars)) {
      throw new IllegalArgumentException(value + " does not fit in " + chars + " SCIP characters");
    }
    char[] c = new char[chars];
    for (int i = chars - 1; i >= 0; i--) {
      c[i] = (char) ((value & 0x3f) + 0x30);
      value >>>= 6;
    }
    return new String(c);
  }

  /**
   * Decodes {@code chars} characters of {@code s} from {@code off}.
   *
   * @throws IllegalArgumentException if a character is outside the encoding's range (0x30–0x6f)
   */
  public static int decode(CharSequence s, int off, int chars) {
    int v = 0;
    for (int i = off; i < off + chars; i++) {
      int c = s.charAt(i) - 0x30;
      if (c < 0 || c > 0x3f) {
        throw new IllegalArgumentException("not a SCIP character: '" + s.charAt(i) + "'");
      }
      v = v << 6 | c;
    }
    return v;
  }

  /** Decodes a whole run of {@code chars}-character numbers. */
  public static int[] decodeAll(CharSequence s, int chars) {
    if (s.length() % chars != 0) {
      throw new IllegalArgumentException(
          "distance data of " + s.length() + " characters is not a whole number of values");
    }
    int[] v = new int[s.length() / chars];
    for (int i = 0; i < v.length; i++) {
      v[i] = decode(s, i * chars, chars);
    }
    return v;
  }

  /**
   * The lines a device sends for a run of encoded data: at most 64 characters each, each followed
   * by its checksum (without the line feeds).
   */
  public static List<String> dataLines(CharSequence encoded) {
    List<String> lines = new ArrayList<>();
    for (int i = 0; i < encoded.length(); i += DATA_LINE) {
      String part = encoded.subSequence(i, Math.min(encoded.length(), i + DATA_LINE)).toString();
      lines.add(part + checksum(part));
    }
    return lines;
  }

  /**
   * A status line ("00" plus its checksum), as the device sends it; status lines' checksums cover
   * both status characters.
   */
  public static String statusLine(String status) {
    return status + checksum(status);
  }

  /**
   * A parameter line of a VV, PP or II answer: {@code NAME:value;} and a checksum that covers the
   * text before the semicolon.
   */
  public static String infoLine(String name, String value) {
    String s = name + ":" + value;
    return s + ";" + checksum(s);
  }
}
