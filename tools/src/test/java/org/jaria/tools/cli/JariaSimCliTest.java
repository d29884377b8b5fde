package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code jaria sim} is reachable through the real command line and runs a bounded session. */
class JariaSimCliTest {

  private final StringWriter out = new StringWriter();
  private final StringWriter err = new StringWriter();

  private int jaria(String... args) {
    CommandLine cl = JariaCli.commandLine();
    cl.setOut(new PrintWriter(out, true));
    cl.setErr(new PrintWriter(err, true));
    return cl.execute(args);
  }

  @Test
  void simHelpListsTheSimulatorsOptions() {
    assertEquals(0, jaria("sim", "--help"), err.toString());
    String usage = out.toString();
    for (String o : new String[] {"--map", "--port", "--unthrottled", "--seconds", "--gui"}) {
      assertTrue(usage.contains(o), o + " in\n" + usage);
    }
  }

  @Test
  void simRunsForItsSecondsAndStops() {
    assertEquals(0, jaria("sim", "--port", "0", "--unthrottled", "--seconds", "2"), err.toString());
    String text = out.toString();
    assertTrue(text.contains("listening on TCP port"), text);
    assertTrue(text.contains("simulator stopped"), text);
  }

  @Test
  void theOldLockstepNameStillRunsWithANote() {
    assertEquals(0, jaria("sim", "--port", "0", "--lockstep", "--seconds", "1"), err.toString());
    assertTrue(err.toString().contains("deprecated"), err.toString());
  }
}
