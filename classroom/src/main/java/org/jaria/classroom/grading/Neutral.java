package org.jaria.classroom.grading;

import java.util.regex.Pattern;

/**
 * Text from a student (their folder's name, what their program printed or threw, the compiler's
 * words about their code) made harmless for where it is shown: a terminal or text file never gets
 * an escape sequence or a carriage return from a student, a spreadsheet never runs a cell as a
 * formula, Markdown and HTML never get raw markup. Plain functions over strings.
 */
public final class Neutral {

  private static final Pattern LINE_BREAKS = Pattern.compile("\r\n?");

  private Neutral() {}

  /**
   * {@code s} with control characters (escape, carriage return, bell...) and the invisible
   * characters that reorder text replaced by '?', tabs by a space; line breaks are kept as '\n'.
   */
  public static String text(String s) {
    String t = LINE_BREAKS.matcher(s).replaceAll("\n");
    StringBuilder sb = null;
    for (int i = 0; i < t.length(); i++) {
      char c = t.charAt(i);
      char r = c;
      if (c == '\t') {
        r = ' ';
      } else if (c != '\n' && unsafe(c)) {
        r = '?';
      }
      if (r != c && sb == null) {
        sb = new StringBuilder(t.substring(0, i));
      }
      if (sb != null) {
        sb.append(r);
      }
    }
    return sb == null ? t : sb.toString();
  }

  /** {@link #text} on one line: line breaks become spaces too. */
  public static String line(String s) {
    return text(s).replace('\n', ' ');
  }

  private static boolean unsafe(char c) {
    return c < 0x20
        || (c >= 0x7F && c <= 0x9F)
        || (c >= '\u200B' && c <= '\u200F')
        || (c >= '\u202A' && c <= '\u202E')
        || (c >= '\u2066' && c <= '\u2069')
        || c == '\uFEFF';
  }

  /**
   * A CSV cell: quoted when it must be, and every line of it that a spreadsheet would read as a
   * formula (starting with =, +, -, @, a tab or a carriage return) guarded with a leading quote.
   */
  public static String csv(String s) {
    String t = LINE_BREAKS.matcher(s).replaceAll("\n");
    StringBuilder sb = new StringBuilder();
    for (String line : t.split("\n", -1)) {
      if (sb.length() > 0) {
        sb.append('\n');
      }
      if (!line.isEmpty() && "=+-@\t\r".indexOf(line.charAt(0)) >= 0) {
        sb.append('\'');
      }
      for (int i = 0; i < line.length(); i++) {
        char c = line.charAt(i);
        sb.append(c != '\t' && unsafe(c) ? '?' : c);
      }
    }
    String cell = sb.toString();
    if (cell.contains(",") || cell.contains("\"") || cell.contains("\n") || cell.startsWith("'")) {
      return "\"" + cell.replace("\"", "\"\"") + "\"";
    }
    return cell;
  }

  /** Markdown text: no raw HTML (&lt;, &gt;, &amp; as entities), no table breaks, no controls. */
  public static String markdown(String s) {
    return html(s)
        .replace("|", "\\|")
        .replace("`", "\\`")
        .replace("*", "\\*")
        .replace("_", "\\_")
        .replace("[", "\\[")
        .replace("]", "\\]");
  }

  /** HTML text: markup characters as entities, no controls. */
  public static String html(String s) {
    return text(s)
        .replace("&", "&amp;")
        .replace("<", "&lt;")
        .replace(">", "&gt;")
        .replace("\"", "&quot;");
  }
}
