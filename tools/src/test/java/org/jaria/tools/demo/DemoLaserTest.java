package org.jaria.tools.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * {@code jaria demo wander --laser}: the simulator's laser reached through the real LMS-200 and URG
 * drivers, as one of the robot's range devices (real time, a few seconds: this checks the wiring).
 */
class DemoLaserTest {

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

  private static void wandersWith(String type, String name) {
    Run r = jaria("demo", "wander", "--laser", type, "--seconds", "2");
    assertEquals(0, r.status(), r.out() + r.err());
    assertTrue(r.out().contains("laser " + name + " connected on tcp"), r.out());
    Matcher m = Pattern.compile("front laser (-?\\d+)mm").matcher(r.out());
    assertTrue(m.find(), r.out());
    int front = Integer.parseInt(m.group(1));
    assertTrue(front > 0, "the laser sees the office ahead: " + r.out());
  }

  @Test
  void wanderAvoidsWithAnLms200() {
    wandersWith("lms2xx", "lms2xx_1");
  }

  @Test
  void wanderAvoidsWithAUrg() {
    wandersWith("urg", "urg_1");
  }

  @Test
  void anUnknownLaserIsRefused() {
    Run r = jaria("demo", "wander", "--laser", "lms5xx", "--seconds", "1");
    assertTrue(r.status() != 0);
    assertTrue((r.out() + r.err()).contains("--laser is lms2xx or urg"), r.out() + r.err());
  }
}
