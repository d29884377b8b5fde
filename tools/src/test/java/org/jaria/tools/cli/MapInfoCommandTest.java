package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code jaria map info} on maps that are cut short or cannot be right. */
class MapInfoCommandTest {

  private static int run(StringWriter out, StringWriter err, String... args) {
    CommandLine cli = JariaCli.commandLine();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(err, true));
    return cli.execute(args);
  }

  @Test
  void aMapCutShortIsShownWithAWarning(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("cut.map");
    Files.writeString(f, "2D-Map\nNumPoints: 4\nDATA\n1 1\n2 2\n");
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    assertEquals(0, run(out, err, "map", "info", f.toString()), err.toString());
    assertTrue(out.toString().contains("warning  " + f + ":2: NumPoints says 4"), out.toString());
  }

  @Test
  void anAbsurdCountIsAnErrorWithTheLine(@TempDir Path dir) throws Exception {
    Path f = dir.resolve("absurd.map");
    Files.writeString(f, "2D-Map\nResolution: 100\nNumPoints: 1000000000000\nDATA\n");
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    assertEquals(1, run(out, err, "map", "info", f.toString()));
    assertTrue(err.toString().contains(f + ":3: NumPoints"), err.toString());
  }

  @Test
  void aMapOverTheSimulatorsBudgetIsRefusedAlikeByMapInfoAndSim(@TempDir Path dir)
      throws Exception {
    Path f = dir.resolve("long-walls.map");
    StringBuilder text = new StringBuilder("2D-Map\nLINES\n");
    for (int i = 0; i < 20_000; i++) {
      // 20,000 walls across a 4 km square: under a megabyte, some 60 million grid cells
      text.append("0 ")
          .append(i * 200)
          .append(" 4000000 ")
          .append(4_000_000 - i * 200)
          .append('\n');
    }
    Files.writeString(f, text.append("DATA\n"));
    StringWriter infoOut = new StringWriter();
    StringWriter infoErr = new StringWriter();
    assertEquals(1, run(infoOut, infoErr, "map", "info", f.toString()), infoOut.toString());
    StringWriter simOut = new StringWriter();
    StringWriter simErr = new StringWriter();
    assertEquals(1, run(simOut, simErr, "sim", "--map", f.toString(), "--seconds", "1"));
    String info = infoErr.toString().strip();
    String sim = simErr.toString().strip();
    assertTrue(info.startsWith("jaria map info: map " + f + " is too big for the simulator"), info);
    assertEquals(
        info.substring("jaria map info: ".length()),
        sim.substring("jaria sim: ".length()),
        "the same refusal");
  }

  @Test
  void aMapThatFitsShowsWhatItCosts() {
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    assertEquals(0, run(out, err, "map", "info", "office"), err.toString());
    assertTrue(out.toString().contains("grid cells in the simulator's index"), out.toString());
  }
}
