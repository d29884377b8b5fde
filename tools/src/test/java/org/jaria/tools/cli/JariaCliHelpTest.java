package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** Every command and subcommand answers --help with its usage, as a user would try first. */
class JariaCliHelpTest {

  private static void collect(CommandLine cl, List<String> path, List<List<String>> out) {
    for (var e : cl.getSubcommands().entrySet()) {
      if (e.getValue().getCommandSpec().aliases().length > 0
          && !e.getKey().equals(e.getValue().getCommandName())) {
        continue; // an alias of a command already listed
      }
      List<String> p = new ArrayList<>(path);
      p.add(e.getKey());
      out.add(p);
      collect(e.getValue(), p, out);
    }
  }

  @Test
  void everyCommandPrintsItsUsageForHelp() {
    List<List<String>> commands = new ArrayList<>();
    collect(JariaCli.commandLine(), List.of(), commands);
    assertTrue(commands.size() > 20, "commands found: " + commands);
    for (List<String> c : commands) {
      if (c.get(c.size() - 1).equals("help")) {
        continue;
      }
      CommandLine cli = JariaCli.commandLine();
      StringWriter out = new StringWriter();
      StringWriter err = new StringWriter();
      cli.setOut(new PrintWriter(out, true));
      cli.setErr(new PrintWriter(err, true));
      List<String> args = new ArrayList<>(c);
      args.add("--help");
      int status = cli.execute(args.toArray(String[]::new));
      String name = String.join(" ", c);
      assertEquals(0, status, "jaria " + name + " --help: " + err);
      assertTrue(
          out.toString().startsWith("Usage: jaria " + name),
          "jaria " + name + " --help prints its usage:\n" + out + err);
      assertTrue(err.toString().isEmpty(), "no complaint for jaria " + name + ": " + err);
    }
  }

  /** Every option's help reads the same way: a capital first letter, one help option. */
  @Test
  void optionHelpIsConsistentAcrossCommands() {
    List<List<String>> commands = new ArrayList<>();
    collect(JariaCli.commandLine(), List.of(), commands);
    List<String> problems = new ArrayList<>();
    for (List<String> c : commands) {
      CommandLine cl = JariaCli.commandLine();
      for (String name : c) {
        cl = cl.getSubcommands().get(name);
      }
      int helpOptions = 0;
      for (CommandLine.Model.OptionSpec o : cl.getCommandSpec().options()) {
        String d = String.join(" ", o.description());
        if (d.isEmpty() || !Character.isUpperCase(d.codePointAt(0))) {
          problems.add("jaria " + String.join(" ", c) + " " + o.longestName() + ": '" + d + "'");
        }
        helpOptions += o.usageHelp() ? 1 : 0;
      }
      if (helpOptions > 1) {
        problems.add("jaria " + String.join(" ", c) + " lists " + helpOptions + " help options");
      }
    }
    assertEquals(List.of(), problems);
  }
}
