package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every command the documentation shows is checked: each {@code ./jaria ...} line parses with the
 * real command line, the quick ones run (in this JVM, with long demos cut to a second), every
 * {@code ./mvnw} line names modules and profiles that exist. (The demos run in {@link
 * DocsDemoCommandsTest}, the getting-started recipes as written in {@link
 * GettingStartedRecipesTest} and {@link BrowserOnlyRecipeTest}, each beside the others.)
 */
@Tag("slow")
class DocsCommandsTest {

  private final Path root = Repo.root();
  private final DocCommands docs = new DocCommands();

  @Test
  void everyJariaCommandParsesAndTheQuickOnesRun(@TempDir Path tmp) throws IOException {
    List<String> commands = docs.lines("./jaria");
    assertTrue(commands.size() >= 25, "only " + commands.size() + " ./jaria commands found");
    DocCommands.Result r = docs.check(commands, sub -> !sub.equals("demo"), tmp);
    assertEquals(List.of(), r.failures());
    assertTrue(r.ran() >= 10, "only " + r.ran() + " commands ran");
  }

  @Test
  void everyMavenCommandNamesRealModulesAndProfiles() throws IOException {
    List<String> commands = docs.lines("./mvnw");
    assertTrue(commands.size() >= 3, commands.toString());
    // -pl names a module folder; -P a profile of the root pom or of a module's pom
    StringBuilder poms = new StringBuilder();
    try (java.util.stream.Stream<Path> s = Files.walk(root, 3)) {
      for (Path p : s.filter(f -> f.getFileName().toString().equals("pom.xml")).toList()) {
        if (!p.toString().contains("/target/")) {
          poms.append(Files.readString(p, StandardCharsets.UTF_8));
        }
      }
    }
    String pom = poms.toString();
    List<String> failures = new ArrayList<>();
    for (String line : commands) {
      List<String> w = ShellWords.split(line);
      for (int i = 1; i < w.size(); i++) {
        String a = w.get(i);
        String value = null;
        if ((a.equals("-pl") || a.equals("-P")) && i + 1 < w.size()) {
          value = w.get(++i);
        } else if (a.startsWith("-P") && a.length() > 2) {
          value = a.substring(2);
        }
        if (value == null) {
          continue;
        }
        for (String v : value.split(",", -1)) {
          boolean ok =
              a.startsWith("-P")
                  ? pom.contains("<id>" + v + "</id>")
                  : Files.isRegularFile(root.resolve(v).resolve("pom.xml"));
          if (!ok) {
            failures.add(line + ": no " + (a.startsWith("-P") ? "profile " : "module ") + v);
          }
        }
      }
    }
    assertEquals(List.of(), failures);
  }
}
