package org.jaria.apps.eztrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class EzTrainCommandTest {

  @TempDir Path dir;

  private static EzTrainOptions parse(String... args) {
    EzTrainCommand c = new EzTrainCommand();
    new CommandLine(c).parseArgs(args);
    return c.options();
  }

  @Test
  void actsOptionsAndScriptingOptions() {
    EzTrainOptions o =
        parse(
            "-p",
            "0",
            "-W",
            "320",
            "-H",
            "240",
            "-w",
            "3",
            "--view",
            "thresh",
            "--channel",
            "7",
            "--train",
            "1,2,3,4",
            "--train",
            "5, 6, 7, 8",
            "--magnification",
            "2");
    assertEquals(0, o.port());
    assertEquals(320, o.width());
    assertEquals(240, o.height());
    assertEquals(3, o.minBlobSize());
    assertEquals(ViewMode.THRESH, o.view());
    assertEquals(7, o.channel());
    assertEquals(2, o.train().size());
    assertArrayEquals(new int[] {5, 6, 7, 8}, o.train().get(1));
    assertEquals(2, o.magnification());
  }

  @Test
  void defaultsAreActs() {
    EzTrainOptions o = parse();
    assertEquals(5001, o.port());
    assertEquals(160, o.width());
    assertEquals(ViewMode.OVERLAY, o.view());
    assertEquals(-1, parse("--no-server").port());
  }

  @Test
  void configGivesTheImageSize() throws Exception {
    Path cfg = dir.resolve("actsconfig");
    Files.writeString(cfg, "Width 320\nHeight 240\n");
    EzTrainOptions o = parse("-c", cfg.toString());
    assertEquals(320, o.width());
    assertEquals(cfg, o.config());
  }

  @Test
  void badValuesAreRefusedWithAReason() {
    for (String[] bad :
        new String[][] {
          {"--train", "1,2,3"},
          {"--train", "a,b,c,d"},
          {"--channel", "33"},
          {"--view", "sideways"},
          {"--magnification", "9"},
          {"-W", "0"}
        }) {
      CommandLine.ParameterException e =
          assertThrows(CommandLine.ParameterException.class, () -> parse(bad));
      assertTrue(e.getMessage().length() > 10, e::getMessage);
    }
  }
}
