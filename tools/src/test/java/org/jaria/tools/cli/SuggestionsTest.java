package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.OptionSpec;

/** "Did you mean": the rule as a function, then through every command of the real command line. */
class SuggestionsTest {

  @Test
  void swapsTyposAndPrefixesAreCloseOthersAreNot() {
    List<String> grade = List.of("--jobs", "--list", "--lang", "--only", "--out", "-o", "-j");
    assertEquals(List.of("--jobs"), Suggestions.similar("--jbos", grade));
    assertEquals(List.of("--list"), Suggestions.similar("--lsit", grade));
    assertEquals(List.of(), Suggestions.similar("--frobnicate", grade));
    assertEquals(List.of("demo"), Suggestions.similar("dmeo", List.of("demo", "sim", "map")));
    assertEquals(List.of("mapper"), Suggestions.similar("mappr", List.of("map", "mapper")));
    assertEquals(
        "--seconds", Suggestions.similar("--sec", List.of("--seed", "--seconds")).get(0), "prefix");
    assertEquals(List.of(), Suggestions.similar("demo", List.of("--demo")), "options for options");
    assertEquals(1, Suggestions.distance("jbos", "jobs"));
    assertEquals(2, Suggestions.distance("sekonds", "seconds") + 1);
  }

  private static String run(String... args) {
    CommandLine cli = JariaCli.commandLine();
    StringWriter err = new StringWriter();
    cli.setErr(new PrintWriter(err, true));
    cli.setOut(new PrintWriter(new StringWriter(), true));
    assertEquals(2, cli.execute(args), String.join(" ", args) + ": " + err);
    return err.toString();
  }

  @Test
  void theIssuesExamples() {
    assertTrue(run("demo", "--sekonds", "3").contains("Did you mean --seconds"));
    assertTrue(run("dmeo").contains("jaria: unknown command 'dmeo'\nDid you mean demo?"));
    assertTrue(run("demo", "wandr").contains("Did you mean wander?"));
    String far = run("sim", "--frobnicate");
    assertTrue(far.contains("Run 'jaria sim --help' for its options."), far);
  }

  /** In every command, a long option with two letters swapped is answered with the option. */
  @Test
  void everyCommandSuggestsItsOwnOptions() {
    List<String> missed = new ArrayList<>();
    int tried = 0;
    for (CommandLine c : all(JariaCli.commandLine(), new ArrayList<>())) {
      for (OptionSpec o : c.getCommandSpec().options()) {
        String name = o.longestName();
        if (o.hidden() || !name.startsWith("--") || name.length() < 7 || o.usageHelp()) {
          continue;
        }
        char[] typo = name.toCharArray();
        char t = typo[3];
        typo[3] = typo[4];
        typo[4] = t;
        String typed = new String(typo);
        if (typed.equals(name)) {
          continue;
        }
        List<String> args = new ArrayList<>(List.of(c.getCommandSpec().qualifiedName().split(" ")));
        args.remove(0);
        args.add(typed);
        String err = run(args.toArray(String[]::new));
        tried++;
        if (!err.contains("Did you mean") || !err.contains(name)) {
          missed.add(args + " -> " + err.strip());
        }
        break; // one option per command
      }
    }
    assertTrue(tried >= 20, "tried " + tried);
    assertEquals(List.of(), missed);
  }

  private static List<CommandLine> all(CommandLine c, List<CommandLine> out) {
    out.add(c);
    c.getSubcommands().values().stream().distinct().forEach(s -> all(s, out));
    return out;
  }
}
