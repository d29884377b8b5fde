package org.jaria.tools.bench.arnl;

import java.io.IOException;
import java.io.StringReader;
import java.util.Locale;
import java.util.SplittableRandom;
import org.jaria.map.ArMap;
import org.jaria.map.MapFormatException;

/**
 * A floor plan no test has seen, generated from a seed for the mapping benchmark: a building whose
 * corridor runs round a central block (so a drive closes loops), with rooms of random widths on the
 * outside, each with a door onto the corridor at a random place.
 */
final class UnseenMap {

  private UnseenMap() {}

  static ArMap generate(long seed) {
    SplittableRandom rng = new SplittableRandom(seed);
    int w = 30000;
    int h = 20000;
    int corridor = 2000;
    int rooms = 4000;
    StringBuilder lines = new StringBuilder();
    int[] count = {0};
    // outer walls
    line(lines, count, 0, 0, w, 0);
    line(lines, count, w, 0, w, h);
    line(lines, count, w, h, 0, h);
    line(lines, count, 0, h, 0, 0);
    // the central block
    int bx0 = rooms + corridor;
    int by0 = rooms + corridor;
    int bx1 = w - rooms - corridor;
    int by1 = h - rooms - corridor;
    line(lines, count, bx0, by0, bx1, by0);
    line(lines, count, bx1, by0, bx1, by1);
    line(lines, count, bx1, by1, bx0, by1);
    line(lines, count, bx0, by1, bx0, by0);
    // rooms along the bottom and top: partitions, and the corridor wall with one door each
    for (int side = 0; side < 2; side++) {
      int wallY = side == 0 ? rooms : h - rooms;
      int outerY = side == 0 ? 0 : h;
      int x = 0;
      while (x < w) {
        int width = Math.min(w - x, 3000 + rng.nextInt(3000));
        if (w - x - width < 2500) {
          width = w - x;
        }
        int door = x + 600 + rng.nextInt(Math.max(1, width - 2200));
        line(lines, count, x, wallY, door, wallY);
        line(lines, count, door + 1000, wallY, x + width, wallY);
        if (x + width < w) {
          line(lines, count, x + width, outerY, x + width, wallY);
        }
        x += width;
      }
    }
    // a pillar in each long corridor
    line(lines, count, w / 3, rooms + 900, w / 3 + 200, rooms + 900);
    line(lines, count, 2 * w / 3, h - rooms - 900, 2 * w / 3 + 200, h - rooms - 900);
    String map =
        String.format(
            Locale.ROOT,
            """
            2D-Map
            MinPos: 0 0
            MaxPos: %d %d
            NumPoints: 0
            Resolution: 20
            LineMinPos: 0 0
            LineMaxPos: %d %d
            NumLines: %d
            Cairn: RobotHome %d %d 0.000000 "" ICON ""
            LINES
            %sDATA
            """,
            w,
            h,
            w,
            h,
            count[0],
            rooms / 2 + rooms / 2 + corridor / 2 + 500,
            rooms + corridor / 2,
            lines);
    try {
      return ArMap.read(new StringReader(map), "unseen-" + seed);
    } catch (MapFormatException | IOException e) {
      throw new IllegalStateException("the generated map does not read: " + e.getMessage(), e);
    }
  }

  private static void line(StringBuilder sb, int[] count, int x1, int y1, int x2, int y2) {
    sb.append(x1).append(' ').append(y1).append(' ').append(x2).append(' ').append(y2).append('\n');
    count[0]++;
  }
}
