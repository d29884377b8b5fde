package org.jaria.tools.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * Every command's {@code --help}, as an 80-column terminal shows it: no line too long, and no
 * sentence broken off after a word or two because the source broke its lines for a wider screen.
 */
class UsageLayoutTest {

  @Test
  void everyUsageFitsEightyColumnsWithoutOrphans() {
    List<String> bad = new ArrayList<>();
    int commands = 0;
    for (CommandLine c : all(JariaCli.commandLine(), new ArrayList<>())) {
      commands++;
      c.setUsageHelpWidth(80);
      StringWriter w = new StringWriter();
      c.usage(new PrintWriter(w, true));
      List<String> lines = w.toString().lines().toList();
      String name = c.getCommandSpec().qualifiedName();
      for (int i = 0; i < lines.size(); i++) {
        String line = lines.get(i);
        if (line.length() > 80) {
          bad.add(name + ": longer than 80 columns: " + line);
        }
        if (line.endsWith(" .") || line.strip().startsWith("/jaria")) {
          bad.add(name + ": a command split at its dot: " + line);
        }
        boolean prose = !line.isEmpty() && !Character.isWhitespace(line.charAt(0));
        String next = i + 1 < lines.size() ? lines.get(i + 1) : "";
        boolean continues = !next.isEmpty() && Character.isLowerCase(next.charAt(0));
        if (prose && continues && line.strip().split(" +").length <= 3) {
          bad.add(name + ": a sentence broken off after '" + line + "' before '" + next + "'");
        }
      }
    }
    assertTrue(commands >= 25, "checked " + commands);
    assertEquals(List.of(), bad);
  }

  private static List<CommandLine> all(CommandLine c, List<CommandLine> out) {
    out.add(c);
    c.getSubcommands().values().stream().distinct().forEach(s -> all(s, out));
    return out;
  }
}
