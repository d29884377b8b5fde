package org.jaria.tools.bench;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The guiServer's rows of {@code jaria bench hostile --quick}: the real user served every time. */
@Tag("slow")
class GuiServerHostileBenchmarkTest {

  @Test
  void theRealUserIsServedDuringEveryAttack() throws Exception {
    String table = GuiServerHostileBenchmark.run(true);
    List<String> rows = table.lines().filter(l -> l.contains(" of ")).toList();
    assertTrue(rows.size() == 3, table);
    for (String r : rows) {
      assertTrue(r.contains(" 5 of 5 "), "served every time:\n" + table);
    }
    assertTrue(table.contains("8 login squatters renewing, one address"), table);
    assertTrue(table.contains("long-string user"), table);
  }
}
