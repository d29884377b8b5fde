package org.jaria.tools.bench;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The squatting rows of {@code jaria bench hostile --quick}: every real client is served. */
@Tag("slow")
class SquatterBenchmarkTest {

  @Test
  void everyRealClientIsServedDuringEveryAttack() throws Exception {
    StringBuilder out = new StringBuilder();
    SquatterBenchmark.rows(out, true);
    String table = out.toString();
    List<String> rows =
        table.lines().filter(l -> l.startsWith("sim: ") || l.startsWith("acts: ")).toList();
    for (String prefix :
        List.of(
            "sim: 2 squatters reconnecting",
            "sim: 10 squatters reconnecting",
            "sim: 50 squatters reconnecting",
            "sim: 16 trickling a garbage byte/s",
            "acts: 16 trickling a garbage byte/s")) {
      String row = rows.stream().filter(l -> l.startsWith(prefix)).findFirst().orElse("");
      assertTrue(row.contains(" 5 of 5 "), "all served: " + prefix + "\n" + table);
      assertTrue(!row.contains(" - "), "cycles measured: " + prefix + "\n" + table);
    }
    assertTrue(table.contains("sim: 200 connects to a robot's port in"), table);
  }
}
