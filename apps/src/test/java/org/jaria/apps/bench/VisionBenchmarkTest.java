package org.jaria.apps.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.testing.SceneChannels;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("slow")
class VisionBenchmarkTest {

  /**
   * The rows, not the figures, are checked, so a short run does ({@code --quick} costs about six
   * seconds of processor time in a full build).
   */
  @Test
  void aShortRunPrintsEveryRow() throws Exception {
    String table = VisionBenchmark.run(new VisionBenchmark.Effort("check", 2_000_000L, 1, 50));
    assertTrue(table.startsWith("JAria ACTS vision benchmark (check)"), table);
    for (String size : new String[] {"160x120", "320x240", "640x480"}) {
      assertEquals(3, table.lines().filter(l -> l.startsWith(size)).count(), table);
    }
    assertTrue(table.contains("256x256"), table);
    assertTrue(table.contains("ACTS server round trip on loopback"), table);
    assertTrue(table.contains("p99"), table);
  }

  @Test
  void benchmarkChannelsAreTrained() {
    ChannelBank bank = SceneChannels.bank(32, 8);
    assertEquals(-1, bank.activeMask(), "all 32 channels can classify");
    for (int i = 0; i < 32; i++) {
      int[] b = SceneChannels.box(i);
      assertTrue(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]);
    }
  }
}
