package org.jaria.tools.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code jaria bench protocol} prints every row, and the SIP path allocates nothing. */
class ProtocolBenchmarkTest {

  /**
   * The rows, not the figures, are checked, so a short run does: {@code --quick} times two million
   * operations three times per rate, about ten seconds of processor time in a full build.
   */
  @Test
  void aShortRunPrintsEveryRow() throws Exception {
    String table = ProtocolBenchmark.run(new ProtocolBenchmark.Effort("check", 1, 50_000, 100));
    List<String> lines = table.lines().toList();
    assertTrue(lines.get(2).startsWith("rates timed on"), table);
    for (String row :
        List.of(
            "SIPs received+decoded per second",
            "SIPs decoded per second",
            "commands encoded per second (VEL)",
            "SIPs encoded per second",
            "bytes allocated per SIP received+decoded")) {
      assertTrue(table.contains(row), row + " missing:\n" + table);
    }
    assertTrue(table.startsWith("JAria protocol benchmark (check)"), table);
    // 100 round trips answered by the client's cycle (a missing VEL fails the run instead).
    assertTrue(table.contains("100 samples"), table);
  }

  @Test
  void receivingAndDecodingASipAllocatesNothing() {
    // Counted by the JVM for this thread: a per-packet object (a boxed number, a new array, a
    // lambda capturing per call) would show as at least several bytes per SIP.
    String perSip =
        ProtocolBenchmark.allocationPerOp(1_000_000, ProtocolBenchmark.receiveAndDecode());
    // HotSpot (every JDK the build supports) counts allocation per thread.
    assertTrue(perSip.endsWith(" B"), "allocation not counted: " + perSip);
    double bytes = Double.parseDouble(perSip.replace(" B", ""));
    assertEquals(0.0, bytes, 1.0, "bytes allocated per SIP: " + perSip);
  }
}
