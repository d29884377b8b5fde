package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The mapping guide's chain, run as written: log on the embedded simulator of a building the robot
 * has never seen, build the map, inspect it, render it in the editor, then localize and navigate on
 * it to goals logged on the way. Files the guide writes in the working directory are written in a
 * temporary folder instead; the Spanish guide shows the same commands.
 */
@Tag("slow")
class MappingRecipeTest {

  private final Path root = Repo.root();

  private List<String> commands(String guide) throws IOException {
    return new GuideRecipes().guideLines(guide, "./jaria ");
  }

  @Test
  void theGuidesChainRunsAsWritten(@TempDir Path tmp) throws IOException {
    List<String> english = commands("docs/mapping.md");
    assertEquals(english, commands("docs/es/mapeo.md"), "both guides show the same commands");
    // The chain; the guiServer's line is run by DocsCommandsTest, the sketch below.
    List<String> chain =
        english.stream().filter(c -> !c.contains("--remote") && !c.contains("guiserver")).toList();
    assertEquals(6, chain.size(), chain.toString());
    for (String line : chain) {
      List<String> words = ShellWords.split(line);
      List<String> args = new ArrayList<>();
      for (String w : words.subList(1, words.size())) {
        boolean file = w.endsWith(".2d") || w.endsWith(".map") || w.endsWith(".png");
        args.add(
            !file ? w : w.contains("/") ? root.resolve(w).toString() : tmp.resolve(w).toString());
      }
      StringWriter out = new StringWriter();
      CommandLine cl = JariaCli.commandLine();
      cl.setOut(new PrintWriter(out));
      cl.setErr(new PrintWriter(out));
      int exit = cl.execute(args.toArray(String[]::new));
      assertEquals(0, exit, line + ":\n" + out);
      System.out.println(line + "\n" + out);
    }
    assertTrue(Files.size(tmp.resolve("lab.2d")) > 100_000, "the log");
    assertTrue(Files.size(tmp.resolve("lab.map")) > 10_000, "the map");
    assertTrue(Files.size(tmp.resolve("lab.png")) > 10_000, "the editor's picture");
    String map = Files.readString(tmp.resolve("lab.map"));
    assertTrue(map.contains("Cairn: RobotHome 0 0 0"), "home where the log started");
    assertTrue(map.contains("\"goal4\""), "the goals logged on the way");
    String sketch = Files.readString(tmp.resolve("lab-sketch.map"));
    assertTrue(sketch.contains("not a map for localization"), "the sketch says what it is");
    assertTrue(Files.size(tmp.resolve("lab-sketch.png")) > 1_000, "the sketch's picture");
  }
}
