package org.jaria.tools.desktop;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * The command line without the apps module (as {@code ./jaria} runs it for every command that needs
 * neither JavaFX nor OpenCV): it starts, lists every desktop app, and an app, a window or a camera
 * benchmark asked for says how to get it instead of failing on a missing class.
 */
class DesktopStandInTest {

  private record Run(int status, String out, String err) {}

  private static Run jaria(String... args) {
    CommandLine cli = JariaCli.commandLine();
    StringWriter out = new StringWriter();
    StringWriter err = new StringWriter();
    cli.setOut(new PrintWriter(out, true));
    cli.setErr(new PrintWriter(err, true));
    int status = cli.execute(args);
    return new Run(status, out.toString(), err.toString());
  }

  @Test
  void theseTestsRunWithoutJavaFxAndWithoutTheApps() {
    assertTrue(Desktop.find().isEmpty(), "no desktop apps on tools' own class path");
    assertThrows(ClassNotFoundException.class, () -> Class.forName("javafx.application.Platform"));
    assertThrows(ClassNotFoundException.class, () -> Class.forName("org.opencv.core.Mat"));
  }

  @Test
  void theHelpListsEveryAppAndEveryBenchmarkOfThem() {
    Run help = jaria("--help");
    assertEquals(0, help.status, help.err);
    for (Desktop.App a : Desktop.APPS) {
      assertTrue(help.out.contains("  " + a.name() + " "), a.name() + " listed:\n" + help.out);
    }
    Run bench = jaria("bench", "--help");
    for (Desktop.App a : Desktop.BENCHMARKS) {
      assertTrue(bench.out.contains("  " + a.name() + " "), a.name() + " listed:\n" + bench.out);
    }
  }

  @Test
  void anAppSaysHowToGetIt() {
    for (Desktop.App a : Desktop.APPS) {
      Run r = jaria(a.name(), "some.map", "--option", "x");
      assertEquals(1, r.status, a.name());
      assertTrue(r.err.startsWith("jaria " + a.name() + ": "), r.err);
      assertTrue(r.err.contains("./jaria") && r.err.contains("JavaFX"), r.err);
      assertEquals("", r.out);
    }
    Run help = jaria("eztrain", "--help");
    assertEquals(0, help.status, help.err);
    assertTrue(help.out.contains("EZ-Train"), help.out);
    Run bench = jaria("bench", "vision", "--quick");
    assertEquals(1, bench.status);
    assertTrue(bench.err.contains("OpenCV"), bench.err);
  }

  @Test
  void aWindowSaysHowToGetItBeforeOpeningAnything() {
    Run sim = jaria("sim", "--gui", "-p", "0");
    assertEquals(1, sim.status);
    assertTrue(sim.err.contains("--gui") && sim.err.contains("./jaria"), sim.err);
    assertFalse(sim.out.contains("listening"), "no port was opened: " + sim.out);
    Run demo = jaria("demo", "--gui", "--seconds", "1");
    assertEquals(1, demo.status);
    assertTrue(demo.err.contains("--gui") && demo.err.contains("JavaFX"), demo.err);
  }
}
