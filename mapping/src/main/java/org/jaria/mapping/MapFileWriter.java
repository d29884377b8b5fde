package org.jaria.mapping;

import java.io.IOException;
import java.io.Writer;
import java.util.List;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;

/**
 * Writes a {@link BuiltMap} as an ARIA {@code .map} file, laid out as Mapper3 lays out maps built
 * from laser logs: the {@code 2D-Map} header with bounds, counts and {@code Resolution}, the
 * objects as {@code Cairn:} lines, then {@code LINES} and {@code DATA}, both sorted.
 */
public final class MapFileWriter {

  private MapFileWriter() {}

  /** Writes {@code m} to {@code out} (not closed). */
  public static void write(BuiltMap m, Writer out) throws IOException {
    StringBuilder sb = new StringBuilder(1 << 16);
    int n = m.pointCount();
    sb.append("2D-Map\n");
    if (n == 0) {
      sb.append("MinPos: 0 0\nMaxPos: 0 0\n");
    } else {
      int minX = Integer.MAX_VALUE;
      int minY = Integer.MAX_VALUE;
      int maxX = Integer.MIN_VALUE;
      int maxY = Integer.MIN_VALUE;
      for (int i = 0; i < n; i++) {
        minX = Math.min(minX, m.x(i));
        minY = Math.min(minY, m.y(i));
        maxX = Math.max(maxX, m.x(i));
        maxY = Math.max(maxY, m.y(i));
      }
      sb.append("MinPos: ").append(minX).append(' ').append(minY).append('\n');
      sb.append("MaxPos: ").append(maxX).append(' ').append(maxY).append('\n');
    }
    sb.append("NumPoints: ").append(n).append('\n');
    sb.append("PointsAreSorted: true\n");
    sb.append("Resolution: ").append(m.resolution()).append('\n');
    List<ArLineSegment> lines = m.lines();
    if (lines.isEmpty()) {
      sb.append("LineMinPos: 0 0\nLineMaxPos: 0 0\n");
    } else {
      long minX = Long.MAX_VALUE;
      long minY = Long.MAX_VALUE;
      long maxX = Long.MIN_VALUE;
      long maxY = Long.MIN_VALUE;
      for (ArLineSegment l : lines) {
        minX = Math.min(minX, Math.round(Math.min(l.x1(), l.x2())));
        minY = Math.min(minY, Math.round(Math.min(l.y1(), l.y2())));
        maxX = Math.max(maxX, Math.round(Math.max(l.x1(), l.x2())));
        maxY = Math.max(maxY, Math.round(Math.max(l.y1(), l.y2())));
      }
      sb.append("LineMinPos: ").append(minX).append(' ').append(minY).append('\n');
      sb.append("LineMaxPos: ").append(maxX).append(' ').append(maxY).append('\n');
    }
    sb.append("NumLines: ").append(lines.size()).append('\n');
    sb.append("LinesAreSorted: true\n");
    for (ArMapObject o : m.objects()) {
      sb.append(o.toMapLine()).append('\n');
    }
    sb.append("LINES\n");
    for (ArLineSegment l : lines) {
      sb.append(Math.round(l.x1())).append(' ').append(Math.round(l.y1())).append(' ');
      sb.append(Math.round(l.x2())).append(' ').append(Math.round(l.y2())).append('\n');
    }
    out.append(sb);
    sb.setLength(0);
    sb.append("DATA\n");
    for (int i = 0; i < n; i++) {
      sb.append(m.x(i)).append(' ').append(m.y(i)).append('\n');
      if (sb.length() > 1 << 16) {
        out.append(sb);
        sb.setLength(0);
      }
    }
    out.append(sb);
    out.flush();
  }
}
