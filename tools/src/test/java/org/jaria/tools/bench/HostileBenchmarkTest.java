package org.jaria.tools.bench;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The flood rows of {@code jaria bench hostile --quick}: every scenario ends with the real client
 * served. (The squatting and guiServer rows are {@link SquatterBenchmarkTest}'s and {@link
 * GuiServerHostileBenchmarkTest}'s.)
 */
class HostileBenchmarkTest {

  @Test
  void quickRunServesTheRealClientsAfterEveryFlood() throws Exception {
    String table = HostileBenchmark.floodsAndReconnects(true);
    java.util.List<String> lines = table.lines().toList();
    assertTrue(lines.get(1).startsWith("sim: 50 silent connections"), table);
    assertTrue(lines.get(2).startsWith("acts: 50 silent connections"), table);
    for (int i = 1; i <= 2; i++) {
      assertTrue(lines.get(i).contains(" yes "), "served after the flood:\n" + table);
    }
    assertTrue(table.contains("5 of 5 reconnects accepted (0 refused)"), table);
  }
}
