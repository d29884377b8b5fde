package org.jaria.classroom.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A grade as a small text file in the student's folder of the report, written by the grader only: a
 * header line, then one tab-separated line per check (points, PASS, FAIL or HELD for a withheld
 * check, name, message; tabs and line breaks escaped), then one line per note ({@code NOTE}, tab,
 * the note). Files of the first version (no HELD, no notes) are read too.
 */
final class GradeFile {

  private static final String HEADER = "jaria-grade 2 ";

  private static final String HEADER_1 = "jaria-grade 1 ";

  private GradeFile() {}

  static void write(Grade g, Path file) throws IOException {
    StringBuilder sb = new StringBuilder(HEADER).append(g.assignment()).append('\n');
    for (Check c : g.checks()) {
      sb.append(c.points())
          .append('\t')
          .append(c.passed() ? "PASS" : c.withheld() ? "HELD" : "FAIL")
          .append('\t')
          .append(escape(c.name()))
          .append('\t')
          .append(escape(c.message()))
          .append('\n');
    }
    for (String n : g.notes()) {
      sb.append("NOTE\t").append(escape(n)).append('\n');
    }
    Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
    Files.writeString(tmp, sb, StandardCharsets.UTF_8);
    Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
  }

  /**
   * Reads a grade file.
   *
   * @throws IOException if it cannot be read or is not a grade file
   */
  static Grade read(Path file) throws IOException {
    List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
    if (lines.isEmpty()
        || !(lines.get(0).startsWith(HEADER) || lines.get(0).startsWith(HEADER_1))) {
      throw new IOException("not a grade file: " + file);
    }
    String assignment = lines.get(0).substring(HEADER.length());
    List<Check> checks = new ArrayList<>();
    List<String> notes = new ArrayList<>();
    for (String line : lines.subList(1, lines.size())) {
      if (line.startsWith("NOTE\t")) {
        notes.add(unescape(line.substring(5)));
        continue;
      }
      String[] f = line.split("\t", 4);
      if (f.length != 4) {
        throw new IOException("bad line in " + file + ": " + line);
      }
      try {
        checks.add(
            new Check(
                unescape(f[2]),
                Integer.parseInt(f[0]),
                f[1].equals("PASS"),
                unescape(f[3]),
                f[1].equals("HELD")));
      } catch (IllegalArgumentException e) {
        throw new IOException("bad line in " + file + ": " + line, e);
      }
    }
    return new Grade(assignment, checks, notes);
  }

  static String escape(String s) {
    return s.replace("\\", "\\\\").replace("\t", "\\t").replace("\n", "\\n").replace("\r", "");
  }

  static String unescape(String s) {
    StringBuilder sb = new StringBuilder(s.length());
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      if (c == '\\' && i + 1 < s.length()) {
        char n = s.charAt(++i);
        sb.append(n == 't' ? '\t' : n == 'n' ? '\n' : n);
      } else {
        sb.append(c);
      }
    }
    return sb.toString();
  }
}
