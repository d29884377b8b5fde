package org.jaria.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jaria.geom.ArLineSegment;

/**
 * Parses map text into an {@link ArMap}. The body (tens of thousands of rows) is scanned straight
 * from the character array with no per-row objects; only header lines become strings.
 */
final class MapReader {

  private static final String LINES_FORM = "'x1 y1 x2 y2' (four numbers, mm)";
  private static final String DATA_FORM = "'x y' (two numbers, mm)";

  private final char[] buf;
  private final String source;
  private final ArMap map;
  private int pos;
  private int lineNo;
  private int lineStart;
  private int lineEnd;
  private int pointCapacityHint = 1024;

  // Row scanning results (reused to avoid allocation).
  private final double[] rowValues = new double[4];
  private boolean rowCanonical;

  private MapReader(char[] buf, String source) {
    this.buf = buf;
    this.source = source;
    this.map = new ArMap(source);
  }

  static ArMap parse(char[] buf, String source) throws MapFormatException {
    MapReader r = new MapReader(buf, source);
    r.run();
    return r.map;
  }

  /** Advances to the next line; false at the end of the text. */
  private boolean nextLine() {
    if (pos >= buf.length) {
      return false;
    }
    lineStart = pos;
    int i = pos;
    while (i < buf.length && buf[i] != '\n') {
      i++;
    }
    lineEnd = i;
    pos = i < buf.length ? i + 1 : i;
    if (lineEnd > lineStart && buf[lineEnd - 1] == '\r') {
      lineEnd--;
    }
    lineNo++;
    return true;
  }

  private String lineText() {
    return new String(buf, lineStart, lineEnd - lineStart);
  }

  private MapFormatException error(String what) {
    return new MapFormatException(source, lineNo, what);
  }

  private void run() throws MapFormatException {
    if (buf.length > 0 && buf[0] == '\uFEFF') {
      map.byteOrderMark = true;
      pos = 1;
    }
    map.endsWithNewline = buf.length > 0 && buf[buf.length - 1] == '\n';
    if (!nextLine()) {
      throw new MapFormatException(
          source, 1, "empty input; a map file starts with a line '2D-Map' (or 2D-Map-Ex...)");
    }
    boolean crlf = pos > 0 && buf[pos - 1] == '\n' && lineEnd < pos - 1;
    map.lineSeparator = crlf ? "\r\n" : "\n";
    String first = lineText();
    String type = first.strip().split("[ \t]", 2)[0];
    if (!type.startsWith("2D-Map")) {
      throw error(
          "not an ArMap file: the first line must be '2D-Map' (or 2D-Map-Ex ... 2D-Map-Ex4), not '"
              + abbreviate(first)
              + "'");
    }
    map.firstLine = first;
    map.mapType = type;
    BodySection.Kind kind = null;
    while (kind == null && nextLine()) {
      kind = sectionKeyword();
      if (kind == null) {
        headerLine();
      }
    }
    while (kind != null) {
      kind = body(kind);
    }
    map.refreshObjects();
  }

  /** The section this line opens (the line is exactly LINES or DATA, blanks aside), else null. */
  private BodySection.Kind sectionKeyword() {
    int a = lineStart;
    int b = lineEnd;
    while (a < b && isBlank(buf[a])) {
      a++;
    }
    while (b > a && isBlank(buf[b - 1])) {
      b--;
    }
    if (b - a == 5 && matches(a, "LINES")) {
      return BodySection.Kind.LINES;
    }
    if (b - a == 4 && matches(a, "DATA")) {
      return BodySection.Kind.DATA;
    }
    return null;
  }

  private boolean matches(int at, String word) {
    for (int i = 0; i < word.length(); i++) {
      if (buf[at + i] != word.charAt(i)) {
        return false;
      }
    }
    return true;
  }

  private static boolean isBlank(char c) {
    return c == ' ' || c == '\t';
  }

  // ------------------------------------------------------------------ header

  private void headerLine() throws MapFormatException {
    for (int i = lineStart; i < lineEnd; i++) {
      char c = buf[i];
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        throw error(
            String.format(
                Locale.ROOT,
                "control character 0x%02X in column %d: this is not a text map file",
                (int) c,
                i - lineStart + 1));
      }
    }
    String raw = lineText();
    String t = raw.stripLeading();
    int colon = t.indexOf(':');
    String key = colon > 0 && isKey(t, colon) ? t.substring(0, colon) : "";
    String rest = key.isEmpty() ? "" : t.substring(colon + 1);
    ArMapObject object = null;
    switch (key) {
      case "Cairn" ->
          object = MapFormat.parseObject(MapFormat.tokenize(rest, source, lineNo), source, lineNo);
      case "MapInfo" ->
          map.mapInfo.add(
              MapFormat.parseMapInfo(
                  MapFormat.tokenize(rest, source, lineNo), raw, source, lineNo));
      case "Resolution" -> map.resolution = (int) Math.round(numbers(key, rest, 1)[0]);
      case "MinPos", "MaxPos", "LineMinPos", "LineMaxPos" -> numbers(key, rest, 2);
      case "NumPoints", "NumLines" -> {
        double n = numbers(key, rest, 1)[0];
        if (n < 0 || n != Math.rint(n)) {
          throw error(key + " must be a whole number >= 0, not '" + rest.strip() + "'");
        }
        if (key.equals("NumPoints")) {
          // Only a capacity hint: never trust it beyond what the text could hold.
          pointCapacityHint = (int) Math.min(n, (buf.length - pos) / 4.0 + 16);
        }
      }
      case "PointsAreSorted", "LinesAreSorted" -> {
        String v = rest.strip();
        if (!v.equalsIgnoreCase("true") && !v.equalsIgnoreCase("false")) {
          throw error(key + " must be true or false, not '" + v + "'");
        }
      }
      default -> {
        // Kept verbatim: Display, Sources, OriginLatLongAlt, CustomInfo, TaskInfo, _Cairn, ...
      }
    }
    map.header.add(new HeaderSlot(key, raw, object));
  }

  private static boolean isKey(String t, int colon) {
    char first = t.charAt(0);
    if (!(Character.isLetter(first) || first == '_')) {
      return false;
    }
    for (int i = 1; i < colon; i++) {
      char c = t.charAt(i);
      if (!(Character.isLetterOrDigit(c) || c == '_')) {
        return false;
      }
    }
    return true;
  }

  private double[] numbers(String key, String rest, int count) throws MapFormatException {
    String[] words = rest.strip().isEmpty() ? new String[0] : rest.strip().split("[ \t]+");
    String form = "'" + key + ":" + " <number>".repeat(count) + "'";
    if (words.length != count) {
      throw error(
          key + " needs " + count + " number(s), found " + words.length + "; expected " + form);
    }
    double[] out = new double[count];
    for (int i = 0; i < count; i++) {
      out[i] = MapFormat.number(words[i], key, source, lineNo, form);
    }
    return out;
  }

  // ------------------------------------------------------------------ body

  /** Reads one section; returns the kind of the next section, or null at the end of the text. */
  private BodySection.Kind body(BodySection.Kind kind) throws MapFormatException {
    for (BodySection s : map.sections) {
      if (s.kind == kind) {
        throw error(
            "a second "
                + kind
                + " section; a map has at most one of each (merge the two or delete one)");
      }
    }
    BodySection section = new BodySection(kind, lineText());
    map.sections.add(section);
    boolean lines = kind == BodySection.Kind.LINES;
    int expected = lines ? 4 : 2;
    int[] xs = null;
    int[] ys = null;
    int n = 0;
    if (!lines) {
      xs = new int[Math.max(16, pointCapacityHint)];
      ys = new int[xs.length];
    }
    boolean canonical = true;
    int bodyStart = pos;
    int bodyEnd = pos;
    BodySection.Kind next = null;
    while (nextLine()) {
      if (startsWithLetter()) {
        next = sectionKeyword();
        if (next != null) {
          break;
        }
      }
      bodyEnd = pos;
      if (isBlankLine()) {
        canonical = false;
        continue;
      }
      scanRow(expected, lines ? LINES_FORM : DATA_FORM, kind);
      canonical &= rowCanonical;
      if (lines) {
        map.lines.add(new ArLineSegment(rowValues[0], rowValues[1], rowValues[2], rowValues[3]));
      } else {
        if (n == xs.length) {
          xs = Arrays.copyOf(xs, n * 2);
          ys = Arrays.copyOf(ys, n * 2);
        }
        xs[n] = toInt(rowValues[0]);
        ys[n] = toInt(rowValues[1]);
        if (xs[n] != rowValues[0] || ys[n] != rowValues[1]) {
          canonical = false;
        }
        n++;
      }
    }
    if (!lines) {
      map.points = ArMapPoints.wrap(xs, ys, n);
    }
    if (!canonical) {
      section.rawRows = splitLines(bodyStart, bodyEnd);
    }
    return next;
  }

  private boolean startsWithLetter() {
    int i = lineStart;
    while (i < lineEnd && isBlank(buf[i])) {
      i++;
    }
    return i < lineEnd && Character.isLetter(buf[i]);
  }

  private boolean isBlankLine() {
    for (int i = lineStart; i < lineEnd; i++) {
      if (!isBlank(buf[i])) {
        return false;
      }
    }
    return true;
  }

  private int toInt(double v) throws MapFormatException {
    if (Math.abs(v) > Integer.MAX_VALUE) {
      throw error("DATA value " + v + " mm is out of range; map coordinates fit in 32-bit ints");
    }
    return (int) Math.round(v);
  }

  /**
   * Scans the current line as {@code expected} numbers into {@link #rowValues}; sets {@link
   * #rowCanonical} if the row is in the form the writer produces (single spaces, plain integers).
   */
  private void scanRow(int expected, String form, BodySection.Kind kind) throws MapFormatException {
    boolean canonical = !isBlank(buf[lineStart]) && !isBlank(buf[lineEnd - 1]);
    int count = 0;
    int i = lineStart;
    while (true) {
      int blanks = 0;
      while (i < lineEnd && isBlank(buf[i])) {
        if (buf[i] == '\t') {
          canonical = false;
        }
        blanks++;
        i++;
      }
      if (blanks > 1) {
        canonical = false;
      }
      if (i >= lineEnd) {
        break;
      }
      if (count == expected) {
        throw rowError(kind, "has more than " + expected + " numbers", form);
      }
      int tokenStart = i;
      boolean neg = false;
      if (buf[i] == '-' || buf[i] == '+') {
        neg = buf[i] == '-';
        canonical &= neg;
        i++;
      }
      int digitsStart = i;
      long v = 0;
      while (i < lineEnd && buf[i] >= '0' && buf[i] <= '9' && i - digitsStart < 18) {
        v = v * 10 + (buf[i] - '0');
        i++;
      }
      int digits = i - digitsStart;
      if (digits > 0 && (i == lineEnd || isBlank(buf[i]))) {
        if ((digits > 1 && buf[digitsStart] == '0') || (neg && v == 0)) {
          canonical = false;
        }
        rowValues[count++] = neg ? -v : v;
        continue;
      }
      // Not a plain integer: a decimal, an exponent, or text.
      while (i < lineEnd && !isBlank(buf[i])) {
        i++;
      }
      String token = new String(buf, tokenStart, i - tokenStart);
      if (!MapFormat.isPlainNumber(token)) {
        throw rowError(kind, "holds '" + abbreviate(token) + "' where a number belongs", form);
      }
      try {
        double d = Double.parseDouble(token);
        if (!Double.isFinite(d)) {
          throw new NumberFormatException(token);
        }
        rowValues[count++] = d;
        canonical = false;
      } catch (NumberFormatException e) {
        throw rowError(kind, "holds '" + abbreviate(token) + "' where a number belongs", form);
      }
    }
    if (count != expected) {
      throw rowError(kind, "has " + count + " number(s)", form);
    }
    rowCanonical = canonical;
  }

  private MapFormatException rowError(BodySection.Kind kind, String what, String form) {
    return error(
        kind + " row '" + abbreviate(lineText()) + "' " + what + "; each row must be " + form);
  }

  private List<String> splitLines(int from, int to) {
    List<String> out = new ArrayList<>();
    int s = from;
    while (s < to) {
      int e = s;
      while (e < to && buf[e] != '\n') {
        e++;
      }
      int end = e > s && buf[e - 1] == '\r' ? e - 1 : e;
      out.add(new String(buf, s, end - s));
      s = e + 1;
    }
    return out;
  }

  private static String abbreviate(String s) {
    return s.length() <= 60 ? s : s.substring(0, 57) + "...";
  }
}
