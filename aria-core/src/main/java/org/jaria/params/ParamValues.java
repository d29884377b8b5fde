package org.jaria.params;

import java.util.Locale;
import java.util.Map;

/**
 * Typed reading of parameter values: numbers, booleans, {@code SonarUnit} and {@code IRUnit} lines.
 * Every failure is a {@link ParamFormatException} naming the entry's file and line.
 */
final class ParamValues {

  /** More sensors than this on one robot is a typo (or a corrupt file), not a robot. */
  static final int MAX_SENSORS = 1024;

  private final Map<String, ParamFile.Entry> raw;

  /**
   * @param raw lower-case keyword to entry; must hold every keyword asked for
   */
  ParamValues(Map<String, ParamFile.Entry> raw) {
    this.raw = raw;
  }

  private ParamFile.Entry entry(String keyword) {
    ParamFile.Entry e = raw.get(keyword.toLowerCase(Locale.ROOT));
    if (e == null) {
      throw new IllegalStateException("built-in defaults lack " + keyword);
    }
    return e;
  }

  String string(String keyword) {
    return entry(keyword).value();
  }

  double number(String keyword) throws ParamFormatException {
    ParamFile.Entry e = entry(keyword);
    return parseDouble(e, e.value(), e.keyword());
  }

  int integer(String keyword) throws ParamFormatException {
    ParamFile.Entry e = entry(keyword);
    return parseInt(e, e.value(), e.keyword());
  }

  boolean bool(String keyword) throws ParamFormatException {
    ParamFile.Entry e = entry(keyword);
    return parseBool(e, e.value(), e.keyword());
  }

  static double parseDouble(ParamFile.Entry e, String text, String what)
      throws ParamFormatException {
    try {
      double d = Double.parseDouble(text);
      if (Double.isFinite(d) && !text.isEmpty() && !endsWithTypeSuffix(text)) {
        return d;
      }
    } catch (NumberFormatException ignored) {
      // reported below
    }
    throw new ParamFormatException(
        e.sourceName(), e.line(), what + " must be a number, not '" + text + "'");
  }

  /** An integer; "500.00000" is accepted (ARIA writes some integers that way), "500.5" is not. */
  static int parseInt(ParamFile.Entry e, String text, String what) throws ParamFormatException {
    try {
      return Integer.parseInt(text);
    } catch (NumberFormatException notPlain) {
      double d;
      try {
        d = Double.parseDouble(text);
      } catch (NumberFormatException notNumber) {
        d = Double.NaN;
      }
      if (d == Math.rint(d) && Math.abs(d) <= Integer.MAX_VALUE && !endsWithTypeSuffix(text)) {
        return (int) d;
      }
      throw new ParamFormatException(
          e.sourceName(), e.line(), what + " must be a whole number, not '" + text + "'");
    }
  }

  /** Java accepts "1f" and "2d" as numbers; a parameter file does not. */
  private static boolean endsWithTypeSuffix(String text) {
    char last = text.isEmpty() ? ' ' : Character.toLowerCase(text.charAt(text.length() - 1));
    return last == 'f' || last == 'd';
  }

  static boolean parseBool(ParamFile.Entry e, String text, String what)
      throws ParamFormatException {
    switch (text.toLowerCase(Locale.ROOT)) {
      case "true", "1" -> {
        return true;
      }
      case "false", "0" -> {
        return false;
      }
      default ->
          throw new ParamFormatException(
              e.sourceName(), e.line(), what + " must be true or false, not '" + text + "'");
    }
  }

  private static String[] fields(ParamFile.Entry e) {
    String v = e.value().strip();
    return v.isEmpty() ? new String[0] : v.split("\\s+");
  }

  private static int unitNumber(ParamFile.Entry e, String text, String kind)
      throws ParamFormatException {
    int n = parseInt(e, text, kind + " number");
    if (n < 0 || n >= MAX_SENSORS) {
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          kind
              + " number "
              + n
              + " is out of range: number units from 0 (below "
              + MAX_SENSORS
              + ")");
    }
    return n;
  }

  /** Parses {@code SonarUnit n x y th} or the MTX form with 6 to 10 fields. */
  static SonarUnit parseSonarUnit(ParamFile.Entry e) throws ParamFormatException {
    String[] f = fields(e);
    if (f.length != 4 && (f.length < 6 || f.length > 10)) {
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          "SonarUnit needs 4 whole numbers '<number> <x mm> <y mm> <heading deg>' (or, for MTX"
              + " sonar, 6 to 10 fields adding <board> <unit> [gain threshold maxRange"
              + " useForDriving]); found "
              + f.length
              + " fields");
    }
    int num = unitNumber(e, f[0], "SonarUnit");
    int x = parseInt(e, f[1], "SonarUnit x");
    int y = parseInt(e, f[2], "SonarUnit y");
    int th = parseInt(e, f[3], "SonarUnit heading");
    if (f.length == 4) {
      return new SonarUnit(num, x, y, th);
    }
    int board = parseInt(e, f[4], "SonarUnit MTX board");
    int unit = parseInt(e, f[5], "SonarUnit MTX board unit");
    int gain = f.length > 6 ? parseInt(e, f[6], "SonarUnit MTX gain") : 0;
    int thresh = f.length > 7 ? parseInt(e, f[7], "SonarUnit MTX detection threshold") : 0;
    int max = f.length > 8 ? parseInt(e, f[8], "SonarUnit MTX max range") : 0;
    boolean use = f.length <= 9 || parseBool(e, f[9], "SonarUnit autonomous driving flag");
    return new SonarUnit(num, x, y, th, board, unit, gain, thresh, max, use);
  }

  /** Parses {@code IRUnit n type cycles x y}. */
  static IRUnit parseIRUnit(ParamFile.Entry e) throws ParamFormatException {
    String[] f = fields(e);
    if (f.length != 5) {
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          "IRUnit needs 5 whole numbers '<number> <type> <cycles> <x mm> <y mm>'; found "
              + f.length
              + " fields");
    }
    int num = unitNumber(e, f[0], "IRUnit");
    return new IRUnit(
        num,
        parseInt(e, f[1], "IRUnit type"),
        parseInt(e, f[2], "IRUnit cycles"),
        parseInt(e, f[3], "IRUnit x"),
        parseInt(e, f[4], "IRUnit y"));
  }

  /** A sensor count: 0 to {@link #MAX_SENSORS}. */
  int count(String keyword) throws ParamFormatException {
    ParamFile.Entry e = entry(keyword);
    int n = parseInt(e, e.value(), e.keyword());
    if (n < 0 || n > MAX_SENSORS) {
      throw new ParamFormatException(
          e.sourceName(),
          e.line(),
          e.keyword() + " " + n + " is not a plausible sensor count (0 to " + MAX_SENSORS + ")");
    }
    return n;
  }
}
