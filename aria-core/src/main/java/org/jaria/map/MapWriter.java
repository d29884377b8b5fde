package org.jaria.map;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.jaria.geom.ArLineSegment;

/**
 * Writes an {@link ArMap}: raw lines where nothing changed, regenerated lines where an edit touched
 * them. Output is buffered and handed to the {@link Writer} in large chunks.
 */
final class MapWriter {

  private static final int CHUNK = 1 << 16;

  private final Writer out;
  private final String sep;
  private final StringBuilder sb = new StringBuilder(CHUNK + 256);
  private boolean pending;

  private MapWriter(Writer out, String sep) {
    this.out = out;
    this.sep = sep;
  }

  static void write(ArMap m, Writer out) throws IOException {
    MapWriter w = new MapWriter(out, m.lineSeparator);
    w.run(m);
  }

  /** Starts a new output line (the separator goes before it, so the last one can be omitted). */
  private void startLine() throws IOException {
    if (pending) {
      sb.append(sep);
    }
    pending = true;
    if (sb.length() >= CHUNK) {
      out.append(sb);
      sb.setLength(0);
    }
  }

  private void line(String s) throws IOException {
    startLine();
    sb.append(s);
  }

  private void run(ArMap m) throws IOException {
    line((m.byteOrderMark ? "\uFEFF" : "") + m.firstLine);
    Set<String> present = new HashSet<>();
    for (HeaderSlot s : m.header) {
      present.add(s.key);
    }
    if (m.pointsEdited) {
      for (String k : List.of("MinPos", "MaxPos", "NumPoints")) {
        if (!present.contains(k)) {
          line(computed(m, k));
        }
      }
    }
    if (m.linesEdited) {
      for (String k : List.of("LineMinPos", "LineMaxPos", "NumLines")) {
        if (!present.contains(k)) {
          line(computed(m, k));
        }
      }
    }
    for (HeaderSlot s : m.header) {
      if (s.object != null) {
        line(s.raw != null ? s.raw : MapFormat.formatObject(s.object));
      } else if ((m.pointsEdited && ArMap.POINT_KEYS.contains(s.key))
          || (m.linesEdited && ArMap.LINE_KEYS.contains(s.key))) {
        line(computed(m, s.key));
      } else {
        line(s.raw);
      }
    }
    for (BodySection s : sectionsToWrite(m)) {
      line(s.keywordLine);
      boolean lines = s.kind == BodySection.Kind.LINES;
      boolean edited = lines ? m.linesEdited : m.pointsEdited;
      if (s.rawRows != null && !edited) {
        for (String r : s.rawRows) {
          line(r);
        }
      } else if (lines) {
        writeLines(m.lines);
      } else {
        writePoints(m.points);
      }
    }
    if (pending && m.endsWithNewline) {
      sb.append(sep);
    }
    out.append(sb);
    sb.setLength(0);
  }

  /** The file's sections, plus LINES (before DATA) and DATA if edits need them. */
  private static List<BodySection> sectionsToWrite(ArMap m) {
    List<BodySection> l = new ArrayList<>(m.sections);
    boolean hasLines = l.stream().anyMatch(s -> s.kind == BodySection.Kind.LINES);
    boolean hasData = l.stream().anyMatch(s -> s.kind == BodySection.Kind.DATA);
    if (!hasLines && !m.lines.isEmpty()) {
      int dataAt = -1;
      for (int i = 0; i < l.size(); i++) {
        if (l.get(i).kind == BodySection.Kind.DATA) {
          dataAt = i;
        }
      }
      BodySection s = new BodySection(BodySection.Kind.LINES, "LINES");
      if (dataAt < 0) {
        l.add(s);
      } else {
        l.add(dataAt, s);
      }
    }
    if (!hasData && (m.pointsEdited || !m.points.isEmpty())) {
      l.add(new BodySection(BodySection.Kind.DATA, "DATA"));
    }
    return l;
  }

  private void writeLines(List<ArLineSegment> lines) throws IOException {
    for (ArLineSegment l : lines) {
      startLine();
      sb.append(MapFormat.formatNumber(l.x1())).append(' ');
      sb.append(MapFormat.formatNumber(l.y1())).append(' ');
      sb.append(MapFormat.formatNumber(l.x2())).append(' ');
      sb.append(MapFormat.formatNumber(l.y2()));
    }
  }

  private void writePoints(ArMapPoints p) throws IOException {
    for (int i = 0; i < p.size(); i++) {
      startLine();
      sb.append(p.x(i)).append(' ').append(p.y(i));
    }
  }

  /** A regenerated count or bounds header line. */
  private static String computed(ArMap m, String key) {
    boolean noPoints = m.points.isEmpty();
    boolean noLines = m.lines.isEmpty();
    return switch (key) {
      case "MinPos" ->
          noPoints ? "MinPos: 0 0" : "MinPos: " + m.pointBound(0) + " " + m.pointBound(1);
      case "MaxPos" ->
          noPoints ? "MaxPos: 0 0" : "MaxPos: " + m.pointBound(2) + " " + m.pointBound(3);
      case "NumPoints" -> "NumPoints: " + m.points.size();
      case "PointsAreSorted" -> "PointsAreSorted: " + m.points.isSorted();
      case "LineMinPos" ->
          noLines ? "LineMinPos: 0 0" : "LineMinPos: " + bound(m, 0) + " " + bound(m, 1);
      case "LineMaxPos" ->
          noLines ? "LineMaxPos: 0 0" : "LineMaxPos: " + bound(m, 2) + " " + bound(m, 3);
      case "NumLines" -> "NumLines: " + m.lines.size();
      case "LinesAreSorted" -> "LinesAreSorted: " + linesSorted(m.lines);
      default -> throw new IllegalArgumentException(key);
    };
  }

  private static String bound(ArMap m, int which) {
    return MapFormat.formatNumber(m.lineBound(which));
  }

  /** Whether lines are in ARIA's order: by x1, then y1, x2, y2. */
  static boolean linesSorted(List<ArLineSegment> lines) {
    for (int i = 1; i < lines.size(); i++) {
      ArLineSegment a = lines.get(i - 1);
      ArLineSegment b = lines.get(i);
      int c = Double.compare(a.x1(), b.x1());
      if (c == 0) {
        c = Double.compare(a.y1(), b.y1());
      }
      if (c == 0) {
        c = Double.compare(a.x2(), b.x2());
      }
      if (c == 0) {
        c = Double.compare(a.y2(), b.y2());
      }
      if (c > 0) {
        return false;
      }
    }
    return true;
  }
}
