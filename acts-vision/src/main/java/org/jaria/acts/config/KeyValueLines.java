package org.jaria.acts.config;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.jaria.acts.ActsFormatException;

/**
 * The line format of JAria's ACTS text files (runtime configuration and preferences), the same
 * style as ARIA's parameter files: one {@code Keyword value...} per line, keywords
 * case-insensitive, values separated by spaces or tabs, a value with spaces in double quotes,
 * comments from {@code ;} or {@code #} (outside quotes) to the end of the line.
 */
final class KeyValueLines {

  /** Text files larger than this are refused. */
  static final long MAX_BYTES = 1 << 20;

  /** One meaningful line. */
  record Line(int number, String key, List<String> values) {
    /** The keyword in lower case. */
    String lowerKey() {
      return key.toLowerCase(Locale.ROOT);
    }
  }

  private KeyValueLines() {}

  /** Reads and splits a file (UTF-8). */
  static List<Line> read(Path file) throws IOException {
    long size = Files.size(file);
    if (size > MAX_BYTES) {
      throw new ActsFormatException(file.toString(), -1, "too large (" + size + " bytes)");
    }
    byte[] bytes = Files.readAllBytes(file);
    String text;
    try {
      text =
          StandardCharsets.UTF_8
              .newDecoder()
              .onMalformedInput(CodingErrorAction.REPORT)
              .onUnmappableCharacter(CodingErrorAction.REPORT)
              .decode(java.nio.ByteBuffer.wrap(bytes))
              .toString();
    } catch (CharacterCodingException e) {
      throw new ActsFormatException(
          file.toString(), -1, "is not a text file (invalid UTF-8); is it the right file?");
    }
    if (text.startsWith("\uFEFF")) {
      text = text.substring(1); // a byte-order mark some editors write
    }
    return parse(text, file.toString());
  }

  /** Splits text into lines. */
  static List<Line> parse(String text, String name) throws ActsFormatException {
    List<Line> out = new ArrayList<>();
    String[] lines = text.split("\r?\n", -1);
    for (int i = 0; i < lines.length; i++) {
      List<String> tokens = tokens(lines[i], name, i + 1);
      if (!tokens.isEmpty()) {
        out.add(new Line(i + 1, tokens.get(0), List.copyOf(tokens.subList(1, tokens.size()))));
      }
    }
    return out;
  }

  private static List<String> tokens(String line, String name, int number)
      throws ActsFormatException {
    List<String> out = new ArrayList<>();
    int i = 0;
    int n = line.length();
    while (i < n) {
      char c = line.charAt(i);
      if (c == ' ' || c == '\t') {
        i++;
      } else if (c == ';' || c == '#') {
        break;
      } else if (c == '"') {
        int end = line.indexOf('"', i + 1);
        if (end < 0) {
          throw new ActsFormatException(name, number, "a quoted value has no closing '\"'");
        }
        out.add(line.substring(i + 1, end));
        i = end + 1;
      } else if (Character.isISOControl(c)) {
        throw new ActsFormatException(
            name, number, "control character in the text; is it the right file?");
      } else {
        int start = i;
        while (i < n && " \t;#\"".indexOf(line.charAt(i)) < 0) {
          i++;
        }
        out.add(line.substring(start, i));
      }
    }
    return out;
  }

  /** Quotes a value if it needs it. */
  static String quote(String value) {
    if (value.isEmpty() || value.matches(".*[ \t;#].*")) {
      return "\"" + value + "\"";
    }
    return value;
  }

  /** The line's single integer value within {@code [min, max]}. */
  static int intValue(Line l, int min, int max, String name) throws ActsFormatException {
    String v = single(l, name);
    try {
      int x = Integer.parseInt(v);
      if (x < min || x > max) {
        throw new ActsFormatException(
            name, l.number(), l.key() + " must be " + min + ".." + max + ", got " + x);
      }
      return x;
    } catch (NumberFormatException e) {
      throw new ActsFormatException(
          name, l.number(), l.key() + " needs a whole number, got '" + v + "'");
    }
  }

  /** The line's single boolean value (true/false, yes/no, on/off, 1/0). */
  static boolean boolValue(Line l, String name) throws ActsFormatException {
    String v = single(l, name).toLowerCase(Locale.ROOT);
    switch (v) {
      case "true", "yes", "on", "1" -> {
        return true;
      }
      case "false", "no", "off", "0" -> {
        return false;
      }
      default ->
          throw new ActsFormatException(
              name, l.number(), l.key() + " needs true or false, got '" + v + "'");
    }
  }

  /** The line's single value; a line with no value gives an empty string. */
  static String stringValue(Line l, String name) throws ActsFormatException {
    if (l.values().isEmpty()) {
      return "";
    }
    return single(l, name);
  }

  private static String single(Line l, String name) throws ActsFormatException {
    if (l.values().size() != 1) {
      throw new ActsFormatException(
          name,
          l.number(),
          l.key() + " takes one value, got " + l.values().size() + " (quote values with spaces)");
    }
    return l.values().get(0);
  }
}
