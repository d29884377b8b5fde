package org.jaria.site;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Code samples pulled out of the repository's own (compiled, tested) source files, so a guide shows
 * code that builds today. A reference is {@code path#name}, relative to the repository root:
 *
 * <ul>
 *   <li>the lines between {@code // tag::name[]} and {@code // end::name[]} (for files written to
 *       be quoted);
 *   <li>otherwise the method, class, record, interface or enum called {@code name}, from its
 *       declaration to its closing brace (for any file, with no markers in it);
 *   <li>{@code path} alone: the whole file, imports included, without its package line.
 * </ul>
 *
 * Every snippet is de-indented so it starts at column 0.
 */
public final class Snippets {

  private static final Pattern TAG = Pattern.compile("^\\s*// (tag|end)::([\\w.-]+)\\[\\]\\s*$");

  private final Path root;

  /** Snippets from the repository at {@code root}. */
  public Snippets(Path root) {
    this.root = root;
  }

  /**
   * The snippet {@code ref} ("path#name" or "path").
   *
   * @throws IOException if the file cannot be read
   * @throws IllegalArgumentException if the file has no such tag or member
   */
  public String get(String ref) throws IOException {
    int hash = ref.indexOf('#');
    String path = hash < 0 ? ref : ref.substring(0, hash);
    String name = hash < 0 ? null : ref.substring(hash + 1);
    Path file = root.resolve(path).normalize();
    if (!Files.isRegularFile(file)) {
      throw new IllegalArgumentException("snippet " + ref + ": no file " + path);
    }
    List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
    List<String> out;
    if (name == null) {
      out = withoutPackage(lines);
    } else {
      out = tagged(lines, name);
      if (out == null) {
        out = member(lines, name);
      }
      if (out == null) {
        throw new IllegalArgumentException(
            "snippet " + ref + ": " + path + " has no tag::" + name + "[] and no member " + name);
      }
    }
    return String.join("\n", dedent(out));
  }

  static List<String> tagged(List<String> lines, String name) {
    List<String> out = new ArrayList<>();
    boolean in = false;
    boolean found = false;
    for (String line : lines) {
      Matcher m = TAG.matcher(line);
      if (m.matches()) {
        if (m.group(2).equals(name)) {
          in = m.group(1).equals("tag");
          found = true;
        }
        continue; // marker lines of any tag are never shown
      }
      if (in && !(line.isBlank() && !out.isEmpty() && out.get(out.size() - 1).isBlank())) {
        out.add(line); // (blank lines left where markers were removed are collapsed)
      }
    }
    return found ? out : null;
  }

  static List<String> member(List<String> lines, String name) {
    Pattern decl =
        Pattern.compile(
            "^\\s*(?:(?:public|protected|private|static|final|abstract|default|synchronized)\\s+)*"
                + "(?:(?:class|record|interface|enum)\\s+"
                + Pattern.quote(name)
                + "\\b|[\\w<>\\[\\],.? ]+\\s+"
                + Pattern.quote(name)
                + "\\s*\\(|"
                + Pattern.quote(name)
                + "\\s*\\()");
    for (int i = 0; i < lines.size(); i++) {
      String l = lines.get(i);
      if (!decl.matcher(l).find() || l.strip().startsWith("//") || l.strip().startsWith("*")) {
        continue;
      }
      if (l.strip().startsWith("return ") || l.contains(" new ") || l.strip().endsWith(";")) {
        continue; // a call, not a declaration
      }
      int end = closingLine(lines, i);
      if (end >= 0) {
        int start = i;
        while (start > 0 && lines.get(start - 1).strip().startsWith("@")) {
          start--; // keep annotations (@Override)
        }
        return new ArrayList<>(lines.subList(start, end + 1));
      }
    }
    return null;
  }

  /** The line holding the brace that closes the first one opened at or after line {@code i}. */
  static int closingLine(List<String> lines, int i) {
    int depth = 0;
    boolean opened = false;
    boolean textBlock = false;
    for (int n = i; n < lines.size(); n++) {
      String l = lines.get(n);
      int k = 0;
      while (k < l.length()) {
        if (textBlock) {
          int close = l.indexOf("\"\"\"", k);
          if (close < 0) {
            break;
          }
          textBlock = false;
          k = close + 3;
          continue;
        }
        char c = l.charAt(k);
        if (l.startsWith("\"\"\"", k)) {
          textBlock = true;
          k += 3;
        } else if (c == '"' || c == '\'') {
          k = skipLiteral(l, k, c);
        } else if (l.startsWith("//", k)) {
          break;
        } else {
          if (c == '{') {
            depth++;
            opened = true;
          } else if (c == '}') {
            depth--;
            if (opened && depth == 0) {
              return n;
            }
          } else if (c == ';' && !opened && depth == 0) {
            return -1; // an abstract or interface method: no body
          }
          k++;
        }
      }
    }
    return -1;
  }

  private static int skipLiteral(String l, int k, char quote) {
    int j = k + 1;
    while (j < l.length() && l.charAt(j) != quote) {
      j += l.charAt(j) == '\\' ? 2 : 1;
    }
    return j + 1;
  }

  static List<String> withoutPackage(List<String> lines) {
    int start = 0;
    for (int i = 0; i < lines.size(); i++) {
      if (lines.get(i).strip().startsWith("package ")) {
        start = i + 1;
        break;
      }
    }
    while (start < lines.size() && lines.get(start).isBlank()) {
      start++;
    }
    return new ArrayList<>(lines.subList(start, lines.size()));
  }

  static List<String> dedent(List<String> lines) {
    int min = Integer.MAX_VALUE;
    for (String l : lines) {
      if (!l.isBlank()) {
        min = Math.min(min, l.length() - l.stripLeading().length());
      }
    }
    List<String> out = new ArrayList<>();
    for (String l : lines) {
      out.add(l.isBlank() ? "" : l.substring(Math.min(min, l.length())).stripTrailing());
    }
    while (!out.isEmpty() && out.get(out.size() - 1).isEmpty()) {
      out.remove(out.size() - 1);
    }
    return out;
  }
}
