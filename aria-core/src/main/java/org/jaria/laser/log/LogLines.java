package org.jaria.laser.log;

import java.io.IOException;
import java.io.Reader;

/**
 * The lines of a scan log, one at a time, in a reused character buffer: no string or object per
 * line or per number, and a line longer than {@link #MAX_LINE} characters is an error rather than a
 * reason to fill the memory. Numbers are parsed straight from the buffer.
 */
final class LogLines {

  /** Longest line accepted: a sweep of 100,000 readings fits with room to spare. */
  static final int MAX_LINE = 4 << 20;

  private static final double[] POW10 = new double[23];

  static {
    POW10[0] = 1;
    for (int i = 1; i < POW10.length; i++) {
      POW10[i] = POW10[i - 1] * 10;
    }
  }

  private final Reader in;
  private final String source;
  private final char[] buf = new char[1 << 16];
  private int bufPos;
  private int bufLen;
  private char[] line = new char[1024];
  private int len;
  private int pos;
  private long lineNo;
  private boolean terminated;
  private boolean eof;

  LogLines(Reader in, String source) {
    this.in = in;
    this.source = source;
  }

  /** The number of the current line (1-based). */
  long lineNo() {
    return lineNo;
  }

  /** Whether the current line ended with a line feed (the last line of a cut-off file does not). */
  boolean terminated() {
    return terminated;
  }

  /**
   * Reads the next line (a trailing carriage return and spaces removed).
   *
   * @return false at the end of the input
   * @throws ScanLogFormatException if the line is too long or holds control characters
   */
  boolean next() throws IOException {
    if (eof) {
      return false;
    }
    len = 0;
    pos = 0;
    boolean any = false;
    while (true) {
      if (bufPos == bufLen) {
        bufLen = in.read(buf, 0, buf.length);
        bufPos = 0;
        if (bufLen <= 0) {
          bufLen = 0;
          eof = true;
          if (!any) {
            return false;
          }
          terminated = false;
          lineNo++;
          trim();
          return true;
        }
      }
      any = true;
      int start = bufPos;
      int end = start;
      while (end < bufLen && buf[end] != '\n') {
        end++;
      }
      append(start, end);
      if (end < bufLen) {
        bufPos = end + 1;
        terminated = true;
        lineNo++;
        trim();
        return true;
      }
      bufPos = bufLen;
    }
  }

  private void append(int from, int to) throws ScanLogFormatException {
    int n = to - from;
    if (len + n > MAX_LINE) {
      throw new ScanLogFormatException(
          source,
          lineNo + 1,
          "line longer than "
              + MAX_LINE
              + " characters: this is not a scan log line (is the file a .2d log?)");
    }
    if (len + n > line.length) {
      char[] bigger = new char[Math.min(MAX_LINE, Math.max(line.length * 2, len + n))];
      System.arraycopy(line, 0, bigger, 0, len);
      line = bigger;
    }
    System.arraycopy(buf, from, line, len, n);
    len += n;
  }

  private void trim() throws ScanLogFormatException {
    while (len > 0 && (line[len - 1] == '\r' || line[len - 1] == ' ' || line[len - 1] == '\t')) {
      len--;
    }
    if (lineNo == 1 && len > 0 && line[0] == '\uFEFF') {
      System.arraycopy(line, 1, line, 0, --len);
    }
    for (int i = 0; i < len; i++) {
      char c = line[i];
      if (c < ' ' && c != '\t') {
        throw new ScanLogFormatException(
            source,
            lineNo,
            String.format(
                "control character 0x%02x at column %d: a scan log is text (is this a .2d log?)",
                (int) c, i + 1));
      }
    }
  }

  /** Whether the current line is empty or a comment. */
  boolean isBlankOrComment() {
    int i = 0;
    while (i < len && (line[i] == ' ' || line[i] == '\t')) {
      i++;
    }
    return i == len || line[i] == '#';
  }

  /** The whole current line. */
  String text() {
    return new String(line, 0, len);
  }

  /** Whether the current line is exactly {@code s}. */
  boolean is(String s) {
    if (len != s.length()) {
      return false;
    }
    for (int i = 0; i < len; i++) {
      if (line[i] != s.charAt(i)) {
        return false;
      }
    }
    return true;
  }

  /**
   * The length of the current line's tag (the text before its first colon, with no space in it), or
   * -1 if the line has none; the value position is set after the colon.
   */
  int tagLength() {
    for (int i = 0; i < len; i++) {
      char c = line[i];
      if (c == ':') {
        pos = i + 1;
        return i;
      }
      if (c == ' ' || c == '\t') {
        return -1;
      }
    }
    return -1;
  }

  /** Whether the tag of the current line (of length {@code tagLen}) is {@code s}. */
  boolean tagIs(int tagLen, String s) {
    if (tagLen != s.length()) {
      return false;
    }
    for (int i = 0; i < tagLen; i++) {
      if (line[i] != s.charAt(i)) {
        return false;
      }
    }
    return true;
  }

  /** The tag of the current line as a string. */
  String tag(int tagLen) {
    return new String(line, 0, tagLen);
  }

  /** The rest of the line after the tag's colon, stripped. */
  String rest() {
    return new String(line, pos, len - pos).strip();
  }

  /** Whether another value follows on the line. */
  boolean hasMore() {
    while (pos < len && (line[pos] == ' ' || line[pos] == '\t')) {
      pos++;
    }
    return pos < len;
  }

  /**
   * The next number of the line; NaN for {@code nan}, {@code inf} and their spellings (C's {@code
   * printf} writes those for damaged values).
   *
   * @throws ScanLogFormatException if the next word is no number ({@code what} says what was
   *     expected)
   */
  double number(String what) throws ScanLogFormatException {
    if (!hasMore()) {
      throw new ScanLogFormatException(source, lineNo, what + ", but the line ends early");
    }
    int start = pos;
    int i = pos;
    boolean neg = false;
    if (line[i] == '-' || line[i] == '+') {
      neg = line[i] == '-';
      i++;
    }
    long mant = 0;
    int digits = 0;
    int exp = 0;
    boolean any = false;
    while (i < len && line[i] >= '0' && line[i] <= '9') {
      if (digits < 18) {
        mant = mant * 10 + (line[i] - '0');
        if (mant != 0) {
          digits++;
        }
      } else {
        exp++;
      }
      any = true;
      i++;
    }
    if (i < len && line[i] == '.') {
      i++;
      while (i < len && line[i] >= '0' && line[i] <= '9') {
        if (digits < 18) {
          mant = mant * 10 + (line[i] - '0');
          if (mant != 0) {
            digits++;
          }
          exp--;
        }
        any = true;
        i++;
      }
    }
    if (any && i < len && (line[i] == 'e' || line[i] == 'E')) {
      int j = i + 1;
      boolean eneg = false;
      if (j < len && (line[j] == '-' || line[j] == '+')) {
        eneg = line[j] == '-';
        j++;
      }
      int e = 0;
      boolean edigits = false;
      while (j < len && line[j] >= '0' && line[j] <= '9') {
        e = Math.min(100_000, e * 10 + (line[j] - '0'));
        edigits = true;
        j++;
      }
      if (edigits) {
        exp += eneg ? -e : e;
        i = j;
      }
    }
    if (!any) {
      return special(start, what);
    }
    if (i < len && line[i] != ' ' && line[i] != '\t') {
      throw bad(start, what);
    }
    pos = i;
    double v;
    if (mant < (1L << 53) && exp >= 0 && exp < POW10.length) {
      v = mant * POW10[exp];
    } else if (mant < (1L << 53) && exp < 0 && -exp < POW10.length) {
      v = mant / POW10[-exp];
    } else {
      v = Double.parseDouble(new String(line, start, i - start));
      return v;
    }
    return neg ? -v : v;
  }

  /** {@code nan}, {@code -nan}, {@code inf}, {@code infinity} (any case): NaN. */
  private double special(int start, String what) throws ScanLogFormatException {
    int end = start;
    while (end < len && line[end] != ' ' && line[end] != '\t') {
      end++;
    }
    int s = start;
    if (line[s] == '-' || line[s] == '+') {
      s++;
    }
    String w = new String(line, s, end - s).toLowerCase(java.util.Locale.ROOT);
    if (w.equals("nan") || w.equals("inf") || w.equals("infinity") || w.startsWith("nan(")) {
      pos = end;
      return Double.NaN;
    }
    throw bad(start, what);
  }

  private ScanLogFormatException bad(int start, String what) {
    int end = start;
    while (end < len && line[end] != ' ' && line[end] != '\t' && end - start < 40) {
      end++;
    }
    return new ScanLogFormatException(
        source, lineNo, what + ", found '" + new String(line, start, end - start) + "'");
  }
}
