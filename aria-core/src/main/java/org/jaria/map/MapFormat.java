package org.jaria.map;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.jaria.geom.ArPose;

/** Text forms of map header lines: tokens, numbers, {@code Cairn:} and {@code MapInfo:} lines. */
final class MapFormat {

  static final String CAIRN_FORM =
      "'Cairn: <Type> <x> <y> <th> \"<description>\" <icon> \"<name>\" [<x1> <y1> <x2> <y2>]"
          + " [\"<description>\"]'";

  /** The longest piece of a file quoted in a message. */
  private static final int EXCERPT_CHARS = 60;

  private MapFormat() {}

  /**
   * A piece of a file fit to quote in a message shown on a terminal: at most {@value
   * #EXCERPT_CHARS} characters, and {@link #printable} (a binary file's bytes would otherwise reach
   * the terminal raw, and some of them are commands to it).
   */
  static String excerpt(String s) {
    String cut = s.length() <= EXCERPT_CHARS ? s : s.substring(0, EXCERPT_CHARS - 3) + "...";
    return printable(cut);
  }

  /**
   * {@code s} with every character that is not printable text (control characters such as ESC, the
   * C1 controls a terminal also obeys, unassigned and private-use code points, the replacement
   * character of undecodable bytes) written as an escape: backslash, x and two hex digits, or
   * backslash, u and four.
   */
  static String printable(String s) {
    StringBuilder sb = null;
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      int type = Character.getType(c);
      boolean bad =
          Character.isISOControl(c)
              || c == '\uFFFD'
              || type == Character.FORMAT
              || type == Character.UNASSIGNED
              || type == Character.PRIVATE_USE
              || type == Character.SURROGATE;
      if (bad && sb == null) {
        sb = new StringBuilder(s.length() + 16).append(s, 0, i);
      }
      if (sb != null) {
        if (!bad) {
          sb.append(c);
        } else if (c < 0x100) {
          sb.append(String.format(Locale.ROOT, "\\x%02X", (int) c));
        } else {
          sb.append(String.format(Locale.ROOT, "\\u%04X", (int) c));
        }
      }
    }
    return sb == null ? s : sb.toString();
  }

  /**
   * Splits {@code text} into words separated by blanks; a double quote starts or ends a quoted
   * stretch in which blanks belong to the word, and the quotes themselves are dropped, so {@code
   * ""} is an empty word and {@code "Label=Measuring stick"} one word.
   *
   * @throws MapFormatException if a quote is not closed
   */
  static List<String> tokenize(String text, String source, int line) throws MapFormatException {
    List<String> out = new ArrayList<>();
    int n = text.length();
    int i = 0;
    StringBuilder sb = new StringBuilder();
    while (i < n) {
      while (i < n && isBlank(text.charAt(i))) {
        i++;
      }
      if (i >= n) {
        break;
      }
      sb.setLength(0);
      boolean quoted = false;
      while (i < n && (quoted || !isBlank(text.charAt(i)))) {
        char c = text.charAt(i++);
        if (c == '"') {
          quoted = !quoted;
        } else {
          sb.append(c);
        }
      }
      if (quoted) {
        throw new MapFormatException(
            source, line, "a double quote is not closed: close it or remove it");
      }
      out.add(sb.toString());
    }
    return out;
  }

  private static boolean isBlank(char c) {
    return c == ' ' || c == '\t';
  }

  /** Integers without a fraction, others in plain decimal notation (never exponents). */
  static String formatNumber(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e15) {
      return Long.toString((long) v);
    }
    return BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
  }

  /** Headings as ARIA writes them ({@code %f}) when that loses nothing, else exactly. */
  static String formatHeading(double th) {
    String f = String.format(Locale.ROOT, "%f", th);
    if (Double.parseDouble(f) == th) {
      return f;
    }
    return BigDecimal.valueOf(th).toPlainString();
  }

  static String formatObject(ArMapObject o) {
    StringBuilder sb = new StringBuilder(80);
    sb.append("Cairn: ").append(o.type()).append(' ');
    sb.append(formatNumber(o.pose().x())).append(' ');
    sb.append(formatNumber(o.pose().y())).append(' ');
    sb.append(formatHeading(o.pose().th()));
    sb.append(" \"").append(o.description()).append("\" ").append(o.iconName());
    sb.append(" \"").append(o.name()).append('"');
    if (o.hasFromTo()) {
      sb.append(' ').append(formatNumber(o.fromPose().x()));
      sb.append(' ').append(formatNumber(o.fromPose().y()));
      sb.append(' ').append(formatNumber(o.toPose().x()));
      sb.append(' ').append(formatNumber(o.toPose().y()));
    }
    return sb.toString();
  }

  /** A finite number, or a clear error naming what it was meant to be. */
  static double number(String token, String what, String source, int line, String form)
      throws MapFormatException {
    try {
      double d = Double.parseDouble(token);
      if (Double.isFinite(d) && isPlainNumber(token)) {
        return d;
      }
    } catch (NumberFormatException ignored) {
      // reported below
    }
    throw new MapFormatException(
        source, line, what + " '" + excerpt(token) + "' is not a number; expected " + form);
  }

  /** Digits, one optional sign, one optional point and exponent: no "NaN", "1f", "0x10". */
  static boolean isPlainNumber(String t) {
    if (t.isEmpty()) {
      return false;
    }
    for (int i = 0; i < t.length(); i++) {
      char c = t.charAt(i);
      boolean ok =
          (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
      if (!ok) {
        return false;
      }
    }
    return true;
  }

  /**
   * Parses the words after {@code Cairn:}.
   *
   * @throws MapFormatException if the count of words or a number is wrong
   */
  static ArMapObject parseObject(List<String> t, String source, int line)
      throws MapFormatException {
    int n = t.size();
    if (n != 7 && n != 8 && n != 11 && n != 12) {
      throw new MapFormatException(
          source,
          line,
          "a Cairn line needs 7 words (11 with from/to corners), plus an optional trailing"
              + " description; found "
              + n
              + ". Expected "
              + CAIRN_FORM);
    }
    String type = t.get(0);
    if (type.isEmpty()) {
      throw new MapFormatException(
          source, line, "Cairn object type is empty; expected " + CAIRN_FORM);
    }
    double x = number(t.get(1), "Cairn x", source, line, CAIRN_FORM);
    double y = number(t.get(2), "Cairn y", source, line, CAIRN_FORM);
    double th = number(t.get(3), "Cairn heading", source, line, CAIRN_FORM);
    String desc = t.get(4);
    String icon = t.get(5);
    String name = t.get(6);
    boolean fromTo = n >= 11;
    ArPose from = null;
    ArPose to = null;
    if (fromTo) {
      from =
          new ArPose(
              number(t.get(7), "Cairn x1", source, line, CAIRN_FORM),
              number(t.get(8), "Cairn y1", source, line, CAIRN_FORM));
      to =
          new ArPose(
              number(t.get(9), "Cairn x2", source, line, CAIRN_FORM),
              number(t.get(10), "Cairn y2", source, line, CAIRN_FORM));
    }
    if (n == 8 || n == 12) {
      // A trailing description replaces the one in the fifth word, as in ARIA.
      desc = t.get(n - 1);
    }
    if (icon.isEmpty()) {
      throw new MapFormatException(
          source, line, "Cairn icon word is empty (use ICON); expected " + CAIRN_FORM);
    }
    try {
      return new ArMapObject(type, new ArPose(x, y, th), desc, icon, name, fromTo, from, to);
    } catch (IllegalArgumentException e) {
      throw new MapFormatException(source, line, e.getMessage());
    }
  }

  /** Parses the words after {@code MapInfo:}. */
  static MapInfoEntry parseMapInfo(List<String> t, String raw, String source, int line)
      throws MapFormatException {
    if (t.isEmpty() || t.get(0).isEmpty()) {
      throw new MapFormatException(
          source,
          line,
          "MapInfo without a type class; expected 'MapInfo: <Class> Name=<name> [Key=Value...]'");
    }
    Map<String, String> attrs = new LinkedHashMap<>();
    for (int i = 1; i < t.size(); i++) {
      String w = t.get(i);
      int eq = w.indexOf('=');
      if (eq < 0) {
        attrs.put(w, "");
      } else {
        attrs.put(w.substring(0, eq), w.substring(eq + 1));
      }
    }
    return new MapInfoEntry(t.get(0), attrs, raw);
  }
}
