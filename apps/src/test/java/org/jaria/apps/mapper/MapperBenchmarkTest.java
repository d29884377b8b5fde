package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.map.ArMap;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.framework.junit5.ApplicationExtension;

/** {@code jaria bench mapper} runs and prints its table (no timing is checked here). */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class MapperBenchmarkTest {

  @Test
  void generatedMapIsTheSizeOfColumbia() {
    ArMap m = MapperBenchmark.generate(60_000, 1);
    assertEquals(60_000, m.getPoints().size());
    assertEquals(500, m.getLines().size());
    assertEquals(31, m.getMapObjects().size());
    assertEquals(m.getPoints(), MapperBenchmark.generate(60_000, 1).getPoints(), "seeded");
  }

  @Test
  void tablesEveryView() throws Exception {
    String table = MapperBenchmark.run(null, 2);
    assertTrue(table.contains("60000 points, 500 lines, 31 objects"), table);
    for (String row :
        new String[] {"whole map in view", "pan, whole map", "zoom in and out", "zoomed in 60x"}) {
      assertTrue(table.lines().anyMatch(l -> l.contains(row) && l.contains(" ms")), row);
    }
  }
}
