package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.jaria.map.ArMap;
import org.jaria.sim.world.MapCost;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A map over the simulator's budget is refused, by what it holds, before a world is built on it: a
 * small file of long walls as surely as a file with too many lines.
 */
class MapBudgetTest {

  /**
   * A 0.8 MB map of 20,000 walls, each crossing a 4 km building: some 60 million grid cells to
   * index, where building the index of bigger ones ran out of memory on the world thread.
   */
  static void writeLongWalls(Path file) throws IOException {
    try (Writer w = Files.newBufferedWriter(file, StandardCharsets.ISO_8859_1)) {
      w.write("2D-Map\nLineMinPos: 0 0\nLineMaxPos: 4000000 4000000\nNumLines: 20000\nLINES\n");
      for (int i = 0; i < 20_000; i++) {
        w.write(String.format(Locale.ROOT, "0 %d 4000000 %d%n", i * 200, 4_000_000 - i * 200));
      }
      w.write("DATA\n");
    }
  }

  @Test
  void longWallsAreRefusedBeforeAWorldIsBuilt(@TempDir Path dir) throws IOException {
    Path big = dir.resolve("long-walls.map");
    writeLongWalls(big);
    IOException e =
        assertThrows(IOException.class, () -> SimWorld.load(big, SimOptions.defaults()).close());
    assertTrue(e.getMessage().contains("too big for the simulator"), e.getMessage());
    assertTrue(e.getMessage().contains("grid cells"), e.getMessage());
    assertTrue(e.getMessage().contains("long-walls.map"), e.getMessage());
  }

  @Test
  void eachCountHasItsLimit() {
    MapBudget b = new MapBudget(10, 20, 30);
    assertNull(b.overBy(new MapCost(10, 20, 30)));
    assertTrue(b.overBy(new MapCost(11, 0, 0)).contains("11 lines"));
    assertTrue(b.overBy(new MapCost(0, 21, 0)).contains("21 points"));
    assertTrue(b.overBy(new MapCost(0, 0, 31)).contains("31 grid cells"));
  }

  @Test
  void aMapWithTooManyLinesIsRefusedByItsCountAlone() {
    ArMap office = ArMap.loadBundled("office");
    MapBudget small = new MapBudget(office.getLines().size() - 1, Long.MAX_VALUE, Long.MAX_VALUE);
    MapBudget.MapTooBigException e =
        assertThrows(
            MapBudget.MapTooBigException.class,
            () -> MapSupport.fromArMap(office, "office", small));
    assertTrue(e.getMessage().startsWith("map office is too big"), e.getMessage());
    assertEquals(
        office.getLines().size(), MapSupport.fromArMap(office, "office").lines().size(), "fits");
  }
}
