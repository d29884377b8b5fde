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
}
