package org.jaria.protocol;

import java.io.ByteArrayOutputStream;

/** Hex dumps of packet bytes, both ways. */
public final class Hex {

  private static final char[] DIGITS = "0123456789ABCDEF".toCharArray();

  private Hex() {}

  /** {@code len} bytes from {@code off} as upper-case pairs separated by single spaces. */
  public static String format(byte[] b, int off, int len) {
    StringBuilder sb = new StringBuilder(len * 3);
    for (int i = 0; i < len; i++) {
      if (i > 0) {
        sb.append(' ');
      }
      int v = b[off + i] & 0xFF;
      sb.append(DIGITS[v >> 4]).append(DIGITS[v & 0xF]);
    }
    return sb.toString();
  }

  /** All of {@code b} as hex pairs. */
  public static String format(byte[] b) {
    return format(b, 0, b.length);
  }

  /**
   * Parses hex text into bytes. Accepts pairs with or without separators (spaces, commas, colons,
   * newlines), an optional {@code 0x} prefix per byte, and {@code #} or {@code //} comments to the
   * end of a line.
   *
   * @throws IllegalArgumentException naming the line and column of the first character that is not
   *     hex
   */
  public static byte[] parse(CharSequence text) {
    ByteArrayOutputStream out = new ByteArrayOutputStream(text.length() / 2);
    int line = 1;
    int col = 0;
    int pending = -1;
    for (int i = 0; i < text.length(); i++) {
      char c = text.charAt(i);
      col++;
      if (c == '\n') {
        line++;
        col = 0;
      }
      if (c == '#' || (c == '/' && i + 1 < text.length() && text.charAt(i + 1) == '/')) {
        while (i < text.length() && text.charAt(i) != '\n') {
          i++;
        }
        i--;
        continue;
      }
      if (c == '0'
          && pending < 0
          && i + 1 < text.length()
          && (text.charAt(i + 1) == 'x' || text.charAt(i + 1) == 'X')) {
        i++;
        col++;
        continue;
      }
      int d = Character.digit(c, 16);
      if (d >= 0) {
        if (pending < 0) {
          pending = d;
        } else {
          out.write((pending << 4) | d);
          pending = -1;
        }
      } else if (Character.isWhitespace(c) || c == ',' || c == ':' || c == ';') {
        if (pending >= 0) {
          out.write(pending);
          pending = -1;
        }
      } else {
        throw new IllegalArgumentException(
            "not a hex digit: '" + c + "' at line " + line + ", column " + col);
      }
    }
    if (pending >= 0) {
      out.write(pending);
    }
    return out.toByteArray();
  }
}
