package org.jaria.map;

import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.jaria.geom.ArLineSegment;

/**
 * Parses map text into an {@link ArMap}, streaming: the text is read a line at a time from a {@link
 * Reader} into one reusable line buffer, so memory follows what the map holds (its points, lines
 * and header), never the file's size, and parsing stops at the first fatal error. The body (tens of
 * thousands of rows) is scanned straight from the line buffer with no per-row objects; only header
 * lines become strings. Counts that cannot be right are errors; a body shorter (or longer) than the
 * header's count is a warning in {@link ArMap#getWarnings()}.
 */
final class MapReader {

  private static final String LINES_FORM = "'x1 y1 x2 y2' (four numbers, mm)";
  private static final String DATA_FORM = "'x y' (two numbers, mm)";

  /** A line longer than this is not a map line (a binary file, or garbage without newlines). */
  static final int MAX_LINE_CHARS = 1 << 20;

  /** More points or lines than this in a header count is a corrupt header, not a map. */
  static final long MAX_COUNT = 1_000_000_000L;

  /** Resolutions (mm per grid cell) outside 1..this are not a map's. */
  static final int MAX_RESOLUTION = 100_000;

  private final Reader in;
  private final String source;
  private final ArMap map;
  private final char[] chunk = new char[64 * 1024];
  private int chunkPos;
  private int chunkLen;
  private boolean eof;

  /** The current line (without its line break) is buf[0 .. lineEnd). */
  private char[] buf = new char[256];

  private final int lineStart = 0;
  private int lineEnd;
  private boolean lineHadBreak;
  private boolean lineHadCr;
  private int lineNo;
  private int pointCapacityHint = 1024;
  private long declaredPoints = -1;
  private long declaredLines = -1;
  private int declaredPointsLine;
  private int declaredLinesLine;

  // Row scanning results (reused to avoid allocation).
  private final double[] rowValues = new double[4];
  private boolean rowCanonical;

  private MapReader(Reader in, String source) {
    this.in = in;
    this.source = source;
    this.map = new ArMap(source);
  }

  /**
   * Parses the map text {@code in} delivers (not closed here).
   *
   * @throws MapFormatException at the first thing that is not a map
   * @throws IOException if reading fails (a {@link java.nio.charset.CharacterCodingException} if
   *     the reader's decoder reports malformed input)
   */
  static ArMap parse(Reader in, String source) throws MapFormatException, IOException {
    MapReader r = new MapReader(in, source);
    r.run();
    return r.map;
  }

  /** Parses map text held in memory. */
  static ArMap parse(char[] text, String source) throws MapFormatException {
    try {
      return parse(new java.io.CharArrayReader(text), source);
    } catch (IOException e) {
      throw new java.io.UncheckedIOException("reading from memory failed", e);
    }
  }

  private boolean fill() throws IOException {
    if (eof) {
      return false;
    }
    int n = in.read(chunk, 0, chunk.length);
    if (n <= 0) {
      eof = n < 0;
      return !eof && fill();
    }
    chunkPos = 0;
    chunkLen = n;
    return true;
  }

  /** Reads the next line into {@link #buf}; false at the end of the text. */
  private boolean nextLine() throws IOException, MapFormatException {
    int len = 0;
    boolean any = false;
    boolean lineBreak = false;
    while (true) {
      if (chunkPos >= chunkLen && !fill()) {
        break;
      }
      any = true;
      int i = chunkPos;
      while (i < chunkLen && chunk[i] != '\n') {
        i++;
      }
      int n = i - chunkPos;
      if (len + n > buf.length) {
        if (len + n > MAX_LINE_CHARS) {
          lineNo++;
          throw error(
              "line longer than " + MAX_LINE_CHARS + " characters: this is not a text map file");
        }
        buf = Arrays.copyOf(buf, Math.min(MAX_LINE_CHARS, Math.max(len + n, buf.length * 2)));
      }
      System.arraycopy(chunk, chunkPos, buf, len, n);
      len += n;
      chunkPos = i;
      if (i < chunkLen) {
        chunkPos++;
        lineBreak = true;
        break;
      }
    }
    if (!any) {
      return false;
    }
    lineHadBreak = lineBreak;
    lineHadCr = len > 0 && buf[len - 1] == '\r';
    lineEnd = lineHadCr ? len - 1 : len;
    lineNo++;
    return true;
  }

  private String lineText() {
    return new String(buf, lineStart, lineEnd - lineStart);
  }

  private MapFormatException error(String what) {
    return new MapFormatException(source, lineNo, what);
  }

  private void run() throws MapFormatException, IOException {
    if (fill() && chunk[0] == '\uFEFF') {
      map.byteOrderMark = true;
      chunkPos = 1;
    }
    if (!nextLine()) {
      map.endsWithNewline = false;
      throw new MapFormatException(
          source, 1, "empty input; a map file starts with a line '2D-Map' (or 2D-Map-Ex...)");
    }
    map.lineSeparator = lineHadBreak && lineHadCr ? "\r\n" : "\n";
    String first = lineText();
    String type = first.strip().split("[ \t]", 2)[0];
    if (!type.startsWith("2D-Map") && !MapFormat.printable(first).equals(first)) {
      throw error(
          "not an ArMap file: it is not text (a map file is text whose first line is '2D-Map');"
              + " it starts with '"
              + abbreviate(first)
              + "'");
    }
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
    map.endsWithNewline = lineHadBreak; // of the last line read
    checkCounts();
    map.refreshObjects();
  }

  /** A body that does not match its header count is a warning the caller can see. */
  private void checkCounts() {
    boolean hasData = false;
    boolean hasLines = false;
    for (BodySection s : map.sections) {
      hasData |= s.kind == BodySection.Kind.DATA;
      hasLines |= s.kind == BodySection.Kind.LINES;
    }
    if (declaredPoints >= 0 && (hasData || declaredPoints > 0)) {
      countWarning(
          "DATA", "points", "NumPoints", declaredPointsLine, map.points.size(), declaredPoints);
    }
    if (declaredLines >= 0 && (hasLines || declaredLines > 0)) {
      countWarning(
          "LINES", "lines", "NumLines", declaredLinesLine, map.lines.size(), declaredLines);
    }
  }

  private void countWarning(
      String section, String what, String key, int line, long found, long declared) {
    if (found < declared) {
      map.warnings.add(
          source
              + ":"
              + line
              + ": "
              + key
              + " says "
              + declared
              + " but the "
              + section
              + " section has only "
              + found
              + " "
              + what
              + "; the file may have been cut short (copy it again, or correct "
              + key
              + ")");
    } else if (found > declared) {
      map.warnings.add(
          source
              + ":"
              + line
              + ": "
              + key
              + " says "
              + declared
              + " but the "
              + section
              + " section has "
              + found
              + " "
              + what
              + "; correct "
              + key);
    }
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
      case "Resolution" -> {
        double r = numbers(key, rest, 1)[0];
        if (!(r >= 1 && r <= MAX_RESOLUTION)) {
          throw error(
              "Resolution must be 1.."
                  + MAX_RESOLUTION
                  + " mm (the size of a grid cell; 100 is usual), not '"
                  + MapFormat.excerpt(rest.strip())
                  + "'");
        }
        map.resolution = (int) Math.round(r);
      }
      case "MinPos", "MaxPos", "LineMinPos", "LineMaxPos" -> numbers(key, rest, 2);
      case "NumPoints", "NumLines" -> {
        double n = numbers(key, rest, 1)[0];
        if (n < 0 || n != Math.rint(n)) {
          throw error(
              key + " must be a whole number >= 0, not '" + MapFormat.excerpt(rest.strip()) + "'");
        }
        if (n > MAX_COUNT) {
          throw error(
              key
                  + " "
                  + MapFormat.excerpt(rest.strip())
                  + " is more than any map holds (at most "
                  + MAX_COUNT
                  + "): the header is corrupt");
        }
        if (key.equals("NumPoints")) {
          declaredPoints = (long) n;
          declaredPointsLine = lineNo;
          // Only a capacity hint: the array grows with what the file really holds.
          pointCapacityHint = (int) Math.min(n, 1 << 20);
        } else {
          declaredLines = (long) n;
          declaredLinesLine = lineNo;
        }
      }
      case "PointsAreSorted", "LinesAreSorted" -> {
        String v = rest.strip();
        if (!v.equalsIgnoreCase("true") && !v.equalsIgnoreCase("false")) {
          throw error(key + " must be true or false, not '" + MapFormat.excerpt(v) + "'");
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
  private BodySection.Kind body(BodySection.Kind kind) throws MapFormatException, IOException {
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
    // Rows are kept as text only once a row is not canonical (the earlier ones are regenerated).
    List<String> raw = null;
    int rows = 0;
    BodySection.Kind next = null;
    while (nextLine()) {
      if (startsWithLetter()) {
        next = sectionKeyword();
        if (next != null) {
          break;
        }
      }
      if (isBlankLine()) {
        if (raw == null) {
          raw = regenerate(lines, rows, 0, xs, ys);
        }
        raw.add(lineText());
        continue;
      }
      scanRow(expected, lines ? LINES_FORM : DATA_FORM, kind);
      boolean rowIsCanonical = rowCanonical;
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
          rowIsCanonical = false;
        }
        n++;
      }
      if (raw == null && !rowIsCanonical) {
        raw = regenerate(lines, rows, lines ? 1 : 0, xs, ys); // this row is in the list already
      }
      if (raw != null) {
        raw.add(lineText());
      }
      rows++;
    }
    if (!lines) {
      map.points = ArMapPoints.wrap(xs, ys, n);
    }
    section.rawRows = raw;
    return next;
  }

  /**
   * The text of the first {@code rows} rows of the section being read, all canonical, so exactly as
   * the writer formats them.
   */
  private List<String> regenerate(boolean lines, int rows, int skipLast, int[] xs, int[] ys) {
    List<String> out = new ArrayList<>(Math.max(16, rows * 2));
    if (lines) {
      List<ArLineSegment> l = map.lines;
      int end = l.size() - skipLast;
      for (int i = end - rows; i < end; i++) {
        ArLineSegment s = l.get(i);
        out.add(
            MapFormat.formatNumber(s.x1())
                + " "
                + MapFormat.formatNumber(s.y1())
                + " "
                + MapFormat.formatNumber(s.x2())
                + " "
                + MapFormat.formatNumber(s.y2()));
      }
    } else {
      for (int i = 0; i < rows; i++) {
        out.add(xs[i] + " " + ys[i]);
      }
    }
    return out;
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

  private static String abbreviate(String s) {
    return MapFormat.excerpt(s);
  }
}
