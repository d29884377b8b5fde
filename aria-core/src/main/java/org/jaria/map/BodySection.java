package org.jaria.map;

import java.util.List;

/**
 * A {@code LINES} or {@code DATA} section as found in the file. Rows in the canonical form (single
 * spaces, plain integers) are regenerated from the parsed numbers when written; a section with any
 * other layout (extra blanks, decimals, blank lines) keeps its raw rows so an unedited map writes
 * back unchanged.
 */
final class BodySection {

  enum Kind {
    LINES,
    DATA
  }

  final Kind kind;

  /** The keyword line as read ("LINES", "DATA", possibly with trailing blanks). */
  final String keywordLine;

  /** The rows as read when they were not canonical, else null. */
  List<String> rawRows;

  BodySection(Kind kind, String keywordLine) {
    this.kind = kind;
    this.keywordLine = keywordLine;
  }
}
