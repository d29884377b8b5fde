package org.jaria.site;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.jaria.tools.cli.JariaCli;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Every command the documentation shows is checked: each {@code ./jaria ...} line parses with the
 * real command line, the quick ones run (in this JVM, with long demos cut to a second), every
 * {@code ./mvnw} line names modules and profiles that exist. (The getting-started recipes run as
 * written in {@link GettingStartedRecipesTest} and {@link BrowserOnlyRecipeTest}.)
 */
@Tag("slow")
class DocsCommandsTest {

  private final Path root = Repo.root();

  /** Subcommands quick and self-contained enough to run as written. */
  private static final Set<String> RUNNABLE =
      Set.of("version", "packets", "map", "demo", "grade", "help", "--help", "--version");

  private List<String> lines(String prefix) throws IOException {
    Set<String> out = new LinkedHashSet<>();
    for (MarkdownBlocks.Block b : MarkdownBlocks.all(root)) {
      if (b.language().equals("java") || b.language().equals("cpp")) {
        continue;
      }
      for (String l : b.text().split("\n", -1)) {
        String s = l.strip();
        s = s.startsWith("$ ") ? s.substring(2) : s;
        if (s.startsWith(prefix)) {
          out.add(s);
        }
      }
    }
    return new ArrayList<>(out);
  }

  @Test
  void everyJariaCommandParsesAndTheQuickOnesRun(@TempDir Path tmp) throws IOException {
    List<String> commands = lines("./jaria");
    assertTrue(commands.size() >= 25, "only " + commands.size() + " ./jaria commands found");
    List<String> failures = new ArrayList<>();
    Set<List<String>> seen = new java.util.HashSet<>();
    int ran = 0;
    for (String line : commands) {
      List<String> words = ShellWords.split(line);
      if (!seen.add(words)) {
        continue; // the same command in another guide (or with another comment)
      }
      String[] args = words.subList(1, words.size()).toArray(String[]::new);
      try {
        JariaCli.commandLine().parseArgs(args);
      } catch (CommandLine.ParameterException e) {
        failures.add(line + "\n    does not parse: " + e.getMessage());
        continue;
      }
      if (args.length == 0 || !RUNNABLE.contains(args[0]) || !pathsExist(args)) {
        continue;
      }
      if (words.contains("--remote")) {
        continue; // needs a robot or simulator already running: RobotFactoryRecipeTest runs those
      }
      List<String> run = new ArrayList<>();
      for (String a : args) {
        run.add(Files.exists(root.resolve(a)) && a.contains("/") ? root.resolve(a).toString() : a);
      }
      if (args[0].equals("demo") && !run.contains("navigate")) {
        // The demos run in real time (30 s by default); a second shows they work.
        int at = run.indexOf("--seconds");
        if (at >= 0 && at + 1 < run.size()) {
          run.set(at + 1, "1");
        } else {
          run.add("--seconds");
          run.add("1");
        }
        if (run.contains("guiserver") && !run.contains("--port")) {
          run.add("--port"); // any free port: the test must not depend on 7272 being free
          run.add("0");
        }
      }
      if (args[0].equals("grade") && !run.contains("-o") && !run.contains("--out")) {
        run.add("--out");
        run.add(tmp.resolve("grade-" + ran).toString());
      }
      StringWriter out = new StringWriter();
      CommandLine cl = JariaCli.commandLine();
      cl.setOut(new PrintWriter(out));
      cl.setErr(new PrintWriter(out));
      long t0 = System.nanoTime();
      int exit = cl.execute(run.toArray(String[]::new));
      System.out.printf("%6d ms  %s%n", (System.nanoTime() - t0) / 1_000_000, line);
      ran++;
      if (exit != 0) {
        failures.add(line + "\n    exited " + exit + ": " + out);
      }
    }
    assertEquals(List.of(), failures);
    assertTrue(ran >= 10, "only " + ran + " commands ran");
  }

  /** Whether every argument that names a file or folder names one in the repository. */
  private boolean pathsExist(String[] args) {
    for (String a : args) {
      boolean pathLike =
          a.contains("/") || a.endsWith(".map") || a.endsWith(".java") || a.endsWith(".ppm");
      if (pathLike && !a.startsWith("-") && !Files.exists(root.resolve(a))) {
        return false;
      }
    }
    return true;
  }

  @Test
  void everyMavenCommandNamesRealModulesAndProfiles() throws IOException {
    List<String> commands = lines("./mvnw");
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
