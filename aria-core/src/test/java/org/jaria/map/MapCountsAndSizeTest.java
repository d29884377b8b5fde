package org.jaria.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Maps cut short, counts and resolutions that cannot be right, and garbage of any size: a warning
 * the caller sees, an error naming the line, and reading that stops at the first fatal error.
 */
class MapCountsAndSizeTest {

  private static ArMap read(String text) throws Exception {
    return ArMap.read(new StringReader(text), "t.map");
  }

  private static String office() throws IOException {
    try (InputStream in = ArMap.class.getResourceAsStream(ArMap.RESOURCE_DIR + "office.map")) {
      return new String(in.readAllBytes(), StandardCharsets.UTF_8);
    }
  }

  @Test
  void aDataSectionShorterThanItsCountIsAWarningNamingTheLine() throws Exception {
    ArMap m = read("2D-Map\nNumPoints: 5\nNumLines: 2\nLINES\n0 0 10 10\nDATA\n1 1\n2 2\n");
    assertEquals(2, m.getPoints().size());
    assertEquals(2, m.getWarnings().size(), m.getWarnings().toString());
    assertTrue(
        m.getWarnings().get(0).startsWith("t.map:2: NumPoints says 5"), m.getWarnings().toString());
    assertTrue(m.getWarnings().get(0).contains("only 2 points"), m.getWarnings().toString());
    assertTrue(
        m.getWarnings().get(1).startsWith("t.map:3: NumLines says 2"), m.getWarnings().toString());
    assertEquals(List.of(), read("2D-Map\nNumPoints: 1\nDATA\n1 1\n").getWarnings());
  }

  @Test
  void theBundledOfficeMapCutInHalfSaysSo(@TempDir Path dir) throws Exception {
    String text = office();
    Path f = dir.resolve("half.map");
    Files.writeString(f, text.substring(0, text.lastIndexOf('\n', text.length() / 2) + 1));
    ArMap m = ArMap.readFile(f);
    assertEquals(1, m.getWarnings().size(), m.getWarnings().toString());
    assertTrue(m.getWarnings().get(0).contains("NumPoints says 2803"), m.getWarnings().get(0));
    assertEquals(List.of(), ArMap.loadBundled("office").getWarnings());
  }

  @Test
  void absurdCountsAndResolutionsAreErrors() {
    for (String[] c :
        new String[][] {
          {"NumPoints: 1000000000000", "NumPoints"},
          {"NumLines: 10000000000", "NumLines"},
          {"Resolution: 0", "Resolution"},
          {"Resolution: -100", "Resolution"},
          {"Resolution: 1e9", "Resolution"},
        }) {
      MapFormatException e =
          assertThrows(MapFormatException.class, () -> read("2D-Map\n" + c[0] + "\nDATA\n"));
      assertEquals(2, e.getLine(), e.getMessage());
      assertTrue(e.getMessage().contains(c[1]), e.getMessage());
    }
  }

  /** Endless seeded random characters, counting what was read. */
  private static final class RandomText extends Reader {
    final SplittableRandom rnd = new SplittableRandom(100);
    final String prefix;
    final char only;
    long read;

    /** {@code prefix}, then random bytes as characters ({@code only} 0), else only {@code only}. */
    RandomText(String prefix, char only) {
      this.prefix = prefix;
      this.only = only;
    }

    RandomText(String prefix) {
      this(prefix, (char) 0);
    }

    @Override
    public int read(char[] b, int off, int len) {
      for (int i = 0; i < len; i++) {
        long at = read++;
        b[off + i] =
            at < prefix.length()
                ? prefix.charAt((int) at)
                : only != 0 ? only : (char) rnd.nextInt(256);
      }
      return len;
    }

    @Override
    public void close() {}
  }

  @Test
  void garbageStopsAtTheFirstFatalErrorWithoutReadingOn() {
    for (String prefix : new String[] {"", "2D-Map\n", "2D-Map\nDATA\n", "2D-Map\nLINES\n"}) {
      RandomText r = new RandomText(prefix);
      MapFormatException e =
          assertThrows(MapFormatException.class, () -> ArMap.read(r, "random"), prefix);
      assertTrue(
          r.read <= MapReader.MAX_LINE_CHARS + 128 * 1024,
          "read " + r.read + " characters before '" + e.getMessage() + "'");
    }
  }

  @Test
  void oneEndlessLineIsRefusedAtTheLineLimit() {
    RandomText endless = new RandomText("2D-Map\nDATA\n", '7');
    MapFormatException e = assertThrows(MapFormatException.class, () -> ArMap.read(endless, "x"));
    assertEquals(3, e.getLine(), e.getMessage());
  }

  /** Seeded truncations of the office map: a map with a warning, or an error with a line. */
  @Test
  void truncatedMapsLoadWithAWarningOrFailWithALine() throws Exception {
    String text = office();
    SplittableRandom rnd = new SplittableRandom(4);
    for (int i = 0; i < 200; i++) {
      int cut = rnd.nextInt(text.length());
      try {
        ArMap m = read(text.substring(0, cut));
        boolean complete = m.getPoints().size() == 2803 && m.getLines().size() == 58;
        assertTrue(complete || !m.getWarnings().isEmpty(), "cut at " + cut + " without a word");
      } catch (MapFormatException e) {
        assertTrue(e.getLine() >= 1, e.getMessage());
      }
    }
  }
}
