package org.jaria.params;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * A parsed robot parameter file ({@code .p}), without any knowledge of what the keywords mean.
 *
 * <p>The format is ARIA's: INI-like text with {@code Section <name>} headers (older files use
 * {@code [Name]}), one {@code Keyword value...} pair per line, and comments that start with {@code
 * ;} (anywhere on a line) or {@code #} (at the start of a line). Keywords are case-insensitive and
 * may repeat ({@code SonarUnit} does, once per sonar). ARIA's own bookkeeping lines ({@code
 * ConfigVersion 2.0}, {@code ;SectionFlags for ...}) are ordinary entries and comments here.
 *
 * <p>What is an error (a {@link ParamFormatException} naming file and line):
 *
 * <ul>
 *   <li>control characters other than tab (a binary file, or a file saved with old Mac CR-only line
 *       ends);
 *   <li>a line whose first word is not a keyword (keywords start with a letter or {@code _} and
 *       contain only letters, digits, {@code _ - . +}), e.g. a wrapped comment that lost its {@code
 *       ;};
 *   <li>{@code Section} or {@code []} without a name, or {@code [Name} without the closing bracket;
 *   <li>input larger than {@value #MAX_CHARS} characters.
 * </ul>
 *
 * <p>Tolerated: blank lines, leading and trailing blanks, CRLF line ends, keywords without a value
 * (the value is then the empty string). What a value <em>means</em> (numbers, booleans, SonarUnit
 * fields) is checked by the typed layer, {@link ArRobotParams}.
 *
 * <p>{@link #write(Writer)} reproduces the input line for line (each with its own line end), so
 * reading and writing a file gives the same text. Instances are immutable.
 */
public final class ParamFile {

  /** The largest input accepted: real files are about 30 k characters. */
  public static final int MAX_CHARS = 4 * 1024 * 1024;

  /**
   * One {@code Keyword value ; comment} line.
   *
   * @param sourceName the file the entry came from
   * @param section the section it is in ("" before the first section header)
   * @param keyword the keyword as written (compare case-insensitively)
   * @param value the value text, trimmed, without the comment ("" if none)
   * @param comment the comment text after {@code ;}, trimmed ("" if none)
   * @param line the 1-based line number
   */
  public record Entry(
      String sourceName, String section, String keyword, String value, String comment, int line) {

    /** "file:line", for messages. */
    public String where() {
      return sourceName + ":" + line;
    }
  }

  /**
   * A section and its entries, in file order.
   *
   * @param name the section name as written ("" for entries before the first header)
   * @param line the line of the header (0 for the implicit first section)
   * @param entries the entries, unmodifiable
   */
  public record Section(String name, int line, List<Entry> entries) {

    /** Copies the entry list. */
    public Section {
      entries = List.copyOf(entries);
    }
  }

  private final String sourceName;
  private final List<String> rawLines;
  private final boolean endsWithNewline;
  private final List<Section> sections;
  private final List<Entry> entries;
  private final Map<String, List<Entry>> byKeyword;

  private ParamFile(
      String sourceName, List<String> rawLines, boolean endsWithNewline, List<Section> sections) {
    this.sourceName = sourceName;
    this.rawLines = List.copyOf(rawLines);
    this.endsWithNewline = endsWithNewline;
    this.sections = List.copyOf(sections);
    List<Entry> all = new ArrayList<>();
    Map<String, List<Entry>> index = new LinkedHashMap<>();
    for (Section s : this.sections) {
      for (Entry e : s.entries()) {
        all.add(e);
        index.computeIfAbsent(key(e.keyword()), k -> new ArrayList<>()).add(e);
      }
    }
    this.entries = List.copyOf(all);
    index.replaceAll((k, v) -> List.copyOf(v));
    this.byKeyword = Collections.unmodifiableMap(index);
  }

  /**
   * Reads a parameter file. The bytes are decoded as ISO-8859-1, which maps every byte to one
   * character, so any comment text survives a {@link #write(Writer)} round trip unchanged.
   *
   * @throws ParamFormatException if the file is not a well-formed parameter file
   * @throws IOException if it cannot be read
   */
  public static ParamFile read(Path file) throws ParamFormatException, IOException {
    long size = Files.size(file);
    if (size > MAX_CHARS) {
      throw new ParamFormatException(
          file.toString(), 0, "file is " + size + " bytes; a parameter file is a small text file");
    }
    byte[] bytes = Files.readAllBytes(file);
    return parse(new String(bytes, StandardCharsets.ISO_8859_1), file.toString());
  }

  /**
   * Reads a parameter file from a character stream (which this method does not close).
   *
   * @param sourceName a name for messages, usually the file name
   * @throws ParamFormatException if the text is not a well-formed parameter file
   * @throws IOException if reading fails
   */
  public static ParamFile read(Reader in, String sourceName)
      throws ParamFormatException, IOException {
    StringBuilder sb = new StringBuilder(32 * 1024);
    char[] buf = new char[8192];
    int n;
    while ((n = in.read(buf)) >= 0) {
      sb.append(buf, 0, n);
      if (sb.length() > MAX_CHARS) {
        throw new ParamFormatException(
            sourceName, 0, "more than " + MAX_CHARS + " characters; not a parameter file");
      }
    }
    return parse(sb.toString(), sourceName);
  }

  /**
   * Parses parameter file text already in memory.
   *
   * @param sourceName a name for messages
   * @throws ParamFormatException if the text is not a well-formed parameter file
   */
  public static ParamFile parse(String text, String sourceName) throws ParamFormatException {
    if (text.length() > MAX_CHARS) {
      throw new ParamFormatException(
          sourceName, 0, "more than " + MAX_CHARS + " characters; not a parameter file");
    }
    List<String> lines = new ArrayList<>();
    int start = 0;
    int len = text.length();
    while (start < len) {
      int nl = text.indexOf('\n', start);
      int end = nl < 0 ? len : nl;
      lines.add(text.substring(start, end));
      start = end + 1;
    }
    boolean endsWithNewline = len > 0 && text.charAt(len - 1) == '\n';

    List<Section> sections = new ArrayList<>();
    String sectionName = "";
    int sectionLine = 0;
    List<Entry> sectionEntries = new ArrayList<>();
    for (int i = 0; i < lines.size(); i++) {
      int lineNo = i + 1;
      String line = lines.get(i);
      if (line.endsWith("\r")) {
        line = line.substring(0, line.length() - 1);
      }
      checkPlainText(line, sourceName, lineNo);
      String t = line.strip();
      if (t.isEmpty() || t.charAt(0) == ';' || t.charAt(0) == '#') {
        continue;
      }
      String header = sectionHeader(t, sourceName, lineNo);
      if (header != null) {
        sections.add(new Section(sectionName, sectionLine, sectionEntries));
        sectionName = header;
        sectionLine = lineNo;
        sectionEntries = new ArrayList<>();
        continue;
      }
      sectionEntries.add(entry(t, sectionName, sourceName, lineNo));
    }
    sections.add(new Section(sectionName, sectionLine, sectionEntries));
    // The implicit section before the first header exists only if something is in it.
    if (sections.get(0).entries().isEmpty()) {
      sections.remove(0);
    }
    return new ParamFile(sourceName, lines, endsWithNewline, sections);
  }

  private static void checkPlainText(String line, String source, int lineNo)
      throws ParamFormatException {
    for (int c = 0; c < line.length(); c++) {
      char ch = line.charAt(c);
      if ((ch < 0x20 && ch != '\t') || ch == 0x7f) {
        throw new ParamFormatException(
            source,
            lineNo,
            String.format(
                Locale.ROOT,
                "control character 0x%02X in column %d: this is not a text parameter file"
                    + " (binary data, or CR-only line ends; save it as plain text)",
                (int) ch,
                c + 1));
      }
    }
  }

  /** The section name if {@code t} (stripped, non-comment) is a section header, else null. */
  private static String sectionHeader(String t, String source, int lineNo)
      throws ParamFormatException {
    if (t.charAt(0) == '[') {
      String body = stripComment(t).strip();
      if (!body.endsWith("]")) {
        throw new ParamFormatException(
            source, lineNo, "section header '" + t + "' lacks the closing ']'");
      }
      String name = body.substring(1, body.length() - 1).strip();
      if (name.isEmpty()) {
        throw new ParamFormatException(source, lineNo, "'[]' section header without a name");
      }
      return name;
    }
    int sp = firstBlank(t);
    String word = sp < 0 ? t : t.substring(0, sp);
    if (word.equalsIgnoreCase("Section")) {
      String name = sp < 0 ? "" : stripComment(t.substring(sp)).strip();
      if (name.isEmpty()) {
        throw new ParamFormatException(
            source, lineNo, "'Section' without a name: write 'Section <name>'");
      }
      return name;
    }
    return null;
  }

  private static Entry entry(String t, String section, String source, int lineNo)
      throws ParamFormatException {
    int end = 0;
    while (end < t.length() && !Character.isWhitespace(t.charAt(end)) && t.charAt(end) != ';') {
      end++;
    }
    String keyword = t.substring(0, end);
    if (!isKeyword(keyword)) {
      throw new ParamFormatException(
          source,
          lineNo,
          "'"
              + abbreviate(t)
              + "' is not a 'Keyword value' line: a keyword starts with a letter and holds only"
              + " letters, digits, '_', '-', '.' or '+' (comment lines start with ';')");
    }
    String rest = t.substring(end);
    int semi = rest.indexOf(';');
    String value = (semi < 0 ? rest : rest.substring(0, semi)).strip();
    String comment = semi < 0 ? "" : rest.substring(semi + 1).strip();
    return new Entry(source, section, keyword, value, comment, lineNo);
  }

  private static boolean isKeyword(String w) {
    if (w.isEmpty()) {
      return false;
    }
    char first = w.charAt(0);
    if (!(isAsciiLetter(first) || first == '_')) {
      return false;
    }
    for (int i = 1; i < w.length(); i++) {
      char c = w.charAt(i);
      if (!(isAsciiLetter(c)
          || (c >= '0' && c <= '9')
          || c == '_'
          || c == '-'
          || c == '.'
          || c == '+')) {
        return false;
      }
    }
    return true;
  }

  private static boolean isAsciiLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  }

  private static int firstBlank(String t) {
    for (int i = 0; i < t.length(); i++) {
      if (Character.isWhitespace(t.charAt(i))) {
        return i;
      }
    }
    return -1;
  }

  private static String stripComment(String s) {
    int semi = s.indexOf(';');
    return semi < 0 ? s : s.substring(0, semi);
  }

  private static String abbreviate(String s) {
    return s.length() <= 60 ? s : s.substring(0, 57) + "...";
  }

  private static String key(String keyword) {
    return keyword.toLowerCase(Locale.ROOT);
  }

  /** The name given when the file was read (usually its path). */
  public String getSourceName() {
    return sourceName;
  }

  /** The value of the first entry with this keyword (case-insensitive), in any section. */
  public Optional<String> get(String keyword) {
    return getEntry(keyword).map(Entry::value);
  }

  /** The first entry with this keyword (case-insensitive), in any section. */
  public Optional<Entry> getEntry(String keyword) {
    List<Entry> l = byKeyword.get(key(keyword));
    return l == null ? Optional.empty() : Optional.of(l.get(0));
  }

  /** The values of every entry with this keyword (case-insensitive), in file order. */
  public List<String> getAll(String keyword) {
    return getAllEntries(keyword).stream().map(Entry::value).toList();
  }

  /** Every entry with this keyword (case-insensitive), in file order. */
  public List<Entry> getAllEntries(String keyword) {
    return byKeyword.getOrDefault(key(keyword), List.of());
  }

  /** Every entry in file order. */
  public List<Entry> entries() {
    return entries;
  }

  /**
   * The section names in file order. Entries before the first header form a section named "",
   * listed only if it has entries (real files start with {@code ConfigVersion 2.0}, so it does).
   */
  public List<String> sectionNames() {
    return sections.stream().map(Section::name).toList();
  }

  /** The sections in file order. */
  public List<Section> sections() {
    return sections;
  }

  /**
   * Writes the file back exactly as it was read: every line unchanged, each with its own line end
   * (LF or CRLF, even mixed), and a final line end only if the input had one.
   */
  public void write(Writer out) throws IOException {
    for (int i = 0; i < rawLines.size(); i++) {
      out.write(rawLines.get(i));
      if (i < rawLines.size() - 1 || endsWithNewline) {
        out.write('\n');
      }
    }
  }

  @Override
  public String toString() {
    return "ParamFile[" + sourceName + ", " + entries.size() + " entries]";
  }
}
