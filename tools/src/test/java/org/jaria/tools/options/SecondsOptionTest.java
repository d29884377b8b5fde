package org.jaria.tools.options;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code --seconds} means the same in every command: seconds to run, 0 no limit, never negative.
 */
class SecondsOptionTest {

  @Test
  void valuesAreSecondsZeroIsNoLimitAndNegativeIsRefused() {
    assertEquals(30, new SecondsOption.Whole().convert("30"));
    assertEquals(0, new SecondsOption.Whole().convert("0"));
    assertEquals(2.5, new SecondsOption.Fractional().convert("2.5"));
    for (String bad : List.of("-3", "-0.5", "NaN", "Infinity", "soon", "")) {
      assertThrows(
          TypeConversionException.class, () -> new SecondsOption.Fractional().convert(bad));
      assertThrows(TypeConversionException.class, () -> new SecondsOption.Whole().convert(bad));
    }
    assertThrows(TypeConversionException.class, () -> new SecondsOption.Whole().convert("1.5"));
  }

  @Test
  void everyCommandWithSecondsRefusesANegativeOneTheSameWay() {
    List<List<String>> commands =
        List.of(
            List.of("demo"),
            List.of("demo", "wander"),
            List.of("demo", "gyro"),
            List.of("demo", "goto"),
            List.of("demo", "chase"),
            List.of("demo", "guiserver"),
            List.of("sim"));
    for (List<String> c : commands) {
      CommandLine cli = JariaCli.commandLine();
      StringWriter err = new StringWriter();
      cli.setErr(new PrintWriter(err, true));
      cli.setOut(new PrintWriter(new StringWriter(), true));
      String[] args =
          java.util.stream.Stream.concat(c.stream(), java.util.stream.Stream.of("--seconds", "-3"))
              .toArray(String[]::new);
      assertEquals(2, cli.execute(args), c + ": " + err);
      assertTrue(err.toString().contains("-3 is not a time to run"), c + ": " + err);
      assertTrue(err.toString().contains("0 for no limit"), c + ": " + err);
    }
  }

  @Test
  void zeroIsAcceptedAndSaidInTheHelp() {
    CommandLine cli = JariaCli.commandLine();
    CommandLine.ParseResult r = cli.parseArgs("sim", "--seconds", "0");
    Double seconds = r.subcommand().matchedOptionValue("--seconds", -1.0);
    assertEquals(0.0, seconds);
    StringWriter help = new StringWriter();
    r.subcommand().commandSpec().commandLine().usage(new PrintWriter(help));
    assertTrue(help.toString().contains("0: run until"), help.toString());
  }
}
